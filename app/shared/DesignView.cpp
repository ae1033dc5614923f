#include "shared/DesignView.h"

#include "shared/RenderService.h"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace marbler::ui {

namespace {

/// The mirror repeat of an image as mirrorRepeat (marbler/Repeat.h) lays it out: the image at
/// the top left, its horizontal mirror at the top right, the vertical mirrors of both below.
QImage mirrorTiled(const QImage& image) {
    const QImage source = image.convertToFormat(QImage::Format_RGB32);
    QImage tiled(source.width() * 2, source.height() * 2, QImage::Format_RGB32);
    QPainter p(&tiled);
    p.drawImage(0, 0, source);
    p.drawImage(source.width(), 0, source.mirrored(true, false));
    p.drawImage(0, source.height(), source.mirrored(false, true));
    p.drawImage(source.width(), source.height(), source.mirrored(true, true));
    return tiled;
}

} // namespace

Region swatchRegion(const Genome& genome) {
    return Region{0.0, 0.0, 2.0 * genome.size.x, 2.0 * genome.size.y};
}

DesignView::DesignView(const Genome& genome, RenderService* renderer, const QString& mesh, bool repeatSwatch,
                       QWidget* parent, bool flatOnObject)
    : QWidget(parent)
    , mGenome(genome)
    , mRenderer(renderer)
    , mMesh(mesh)
    , mFlatOnObject(flatOnObject && genome.dimension != 3)
    , mOnObject(genome.dimension == 3 || mFlatOnObject)
    , mKey(renderer->newKey())
    , mAngle(viewAngleOf(mGenome))
    , mSwatch(repeatSwatch && !mOnObject) {
    setObjectName(QStringLiteral("designView"));
    setMinimumSize(320, 320);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setToolTip(mOnObject ? tr("Drag to turn the object; wheel, + and - zoom")
                         : tr("Wheel, + and - zoom about the pointer; drag to pan"));
    mViewController.setDesignSize(mGenome.size.x, mGenome.size.y);
    mMessage = tr("rendering…");
    connect(mRenderer, &RenderService::rendered, this,
            [this](std::uint64_t key, const QImage& image, bool final) {
                if (key != mKey) return;
                // The service delivers only the newest request's results: they show its view.
                mImageSwatch = mRequestSwatch;
                // Tiled once here, not at each paint (the tile is fitted to half the canvas). A
                // bath that wraps came tiled on its own lattice, by the renderer (swatchRegion).
                mImage = mImageSwatch && !mGenome.wrap ? mirrorTiled(image) : image;
                mImageFinal = final;
                if (mRequestRegion) mImageRegion = *mRequestRegion;
                mImageZoom = mRequestZoom;
                mMessage.clear();
                update();
            });
    connect(mRenderer, &RenderService::failed, this, [this](std::uint64_t key, const QString& message) {
        if (key != mKey) return;
        mImage = QImage();
        mMessage = tr("Cannot render: %1").arg(message);
        update();
    });
}

DesignView::~DesignView() {
    mRenderer->cancel(mKey);
}

void DesignView::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), palette().color(QPalette::Window).darker(115));
    if (!mImage.isNull()) {
        p.setRenderHint(QPainter::SmoothPixmapTransform);
        p.drawImage(imageTarget(), mImage);
    }
    if (!mMessage.isEmpty()) {
        p.setPen(palette().color(QPalette::WindowText));
        p.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, mMessage);
    }
}

void DesignView::wheelEvent(QWheelEvent* event) {
    // Ctrl+wheel zooms too (as in most viewers); a notch (120) is the keys' step, √2.
    const double notches = event->angleDelta().y() / 120.0;
    if (notches != 0.0) zoomAt(std::pow(std::sqrt(2.0), notches), event->position());
    event->accept();
}

QString DesignView::zoomText() const {
    const double percent = 100.0 * (mOnObject ? mObjectZoom : mViewController.scale());
    return tr("%L1 %").arg(percent, 0, 'f', percent < 10.0 ? 1 : 0);
}

void DesignView::resizeEvent(QResizeEvent*) {
    mViewController.setViewport(size() * devicePixelRatioF());
    viewChanged();
}

void DesignView::zoomIn() {
    zoomAt(std::sqrt(2.0), QRectF(rect()).center());
}
void DesignView::zoomOut() {
    zoomAt(1.0 / std::sqrt(2.0), QRectF(rect()).center());
}

void DesignView::zoomAt(double factor, QPointF anchor) {
    if (mSection) return; // the cross-section is shown whole
    if (mOnObject)
        // A solid zooms about its framed centre: its camera always looks there.
        mObjectZoom = std::clamp(mObjectZoom * factor, 0.25, 16.0);
    else
        mViewController.zoomBy(factor, anchor * devicePixelRatioF());
    viewChanged();
}

void DesignView::fitView() {
    mObjectZoom = 1.0;
    mViewController.fit();
    viewChanged();
}

void DesignView::showOneToOne() {
    if (mOnObject) return;
    mViewController.oneToOne();
    viewChanged();
}

void DesignView::panBy(QPointF delta) {
    if (mOnObject) return;
    mViewController.panBy(delta * devicePixelRatioF());
    viewChanged();
}

void DesignView::viewChanged(bool previewOnly) {
    emit zoomChanged();
    update(); // the image shown so far, moved and scaled to the new view at once
    requestRender(previewOnly);
}

QRectF DesignView::imageTarget() const {
    const double ratio = devicePixelRatioF();
    if (mImageSwatch) {
        // Rendered at its size on the canvas: centred, never scaled.
        QRectF target(QPointF(0, 0), QSizeF(mImage.size()) / ratio);
        target.moveCenter(QRectF(rect()).center());
        return target;
    }
    if (!mOnObject) {
        const QRectF r = mViewController.toViewport(mImageRegion);
        return QRectF(r.topLeft() / ratio, r.size() / ratio);
    }
    // A solid's image fills the canvas (a cross-section keeps its proportions), magnified by
    // the zoom asked for since.
    const QRectF area(rect());
    const double zoom = mSection ? 1.0 : mObjectZoom / mImageZoom;
    const QSizeF size = QSizeF(mImage.size()).scaled(area.size(), Qt::KeepAspectRatio) * zoom;
    QRectF target(QPointF(0, 0), size);
    target.moveCenter(area.center());
    return target;
}

void DesignView::requestRender(bool previewOnly) {
    RenderRequest request;
    request.genome = mGenome;
    request.mesh = mMesh;
    request.flatOnObject = mFlatOnObject;
    request.yaw = mAngle.yaw;
    request.pitch = mAngle.pitch;
    request.zoom = mObjectZoom;
    request.previewOnly = previewOnly;
    const QSize viewport = (size() * devicePixelRatioF()).expandedTo(QSize(32, 32));
    mRequestSwatch = mSwatch && !mOnObject;
    if (mSection && mGenome.dimension == 3) {
        // The whole cross-section, fitted into the canvas with its own proportions.
        request.slice = mSection;
        request.size = viewport;
        request.zoom = 1.0;
    } else if (mOnObject) {
        request.size = viewport;
    } else if (mRequestSwatch && mGenome.wrap) {
        // A bath that wraps (issue 29): the design repeats on its own lattice, straight,
        // half-drop or brick, so the swatch is the render of the plane two tiles a side, exact
        // where a copy of a half-drop tile would fall between pixels, fitted into the canvas.
        const Region r = swatchRegion(mGenome);
        const double w = r.x1 - r.x0, h = r.y1 - r.y0;
        const double scale = std::min(viewport.width() / w, viewport.height() / h);
        // Two whole pixels' worth a tile: its copies then fall on the same pixels.
        request.size = QSize(2 * std::max(8, int(std::floor(w * scale / 2))),
                             2 * std::max(8, int(std::floor(h * scale / 2))));
        request.region = r;
    } else if (mRequestSwatch) {
        // The whole design, whatever the zoom (the swatch judges the repeat, not a detail),
        // fitted into half the canvas: tiled 2 x 2 it fills the canvas. The service fits the
        // design's proportions into this size.
        request.size = (viewport / 2).expandedTo(QSize(16, 16));
        request.region.reset();
    } else {
        // Only the part of the design in view, at the view's scale: exact at any zoom.
        const auto window = mViewController.visibleWindow();
        if (!window) {
            mRenderer->cancel(mKey);
            mImage = QImage();
            update();
            return;
        }
        request.region = window->region;
        request.size = window->pixels.size();
    }
    mRequestRegion = request.region;
    mRequestZoom = mSection ? 1.0 : mObjectZoom;
    mImageFinal = false; // what is shown now stands in for the view until its render comes
    mRenderer->request(mKey, std::move(request));
}

void DesignView::mousePressEvent(QMouseEvent* event) {
    mLastPos = event->position();
    mDragging = event->button() == Qt::LeftButton;
    if (mDragging && !mOnObject) setCursor(Qt::ClosedHandCursor);
}

void DesignView::mouseMoveEvent(QMouseEvent* event) {
    if (!mDragging) return;
    const QPointF d = event->position() - mLastPos;
    mLastPos = event->position();
    // A cross-section does not turn: the section controls move it.
    if (mSection) return;
    // While dragging only the quick pass is worth rendering; the release asks for the final one.
    if (!mOnObject)
        mViewController.panBy(d * devicePixelRatioF());
    else
        mAngle = mAngle.dragged(d.x(), d.y());
    viewChanged(true);
}

void DesignView::mouseReleaseEvent(QMouseEvent*) {
    if (!mDragging) return;
    mDragging = false;
    unsetCursor();
    requestRender();
    if (!mOnObject || mSection) return;
    // The angle belongs to the design: saved with it, and given back to its cell.
    setViewAngle(mGenome, mAngle);
    emit viewAngleChanged(mAngle);
}

void DesignView::setRepeatSwatch(bool on) {
    if (mOnObject) on = false;
    if (on == mSwatch) return;
    mSwatch = on;
    viewChanged();
}

void DesignView::setSection(const std::optional<Slice>& slice) {
    if (mGenome.dimension != 3) return;
    mSection = slice;
    setToolTip(mSection ? tr("The cross-section: the section controls below move and turn it")
                        : tr("Drag to turn the object; wheel, + and - zoom"));
    viewChanged();
}

} // namespace marbler::ui
