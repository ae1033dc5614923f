// A solid design on its object (SolidObjectView.h).

#include "editor/SolidObjectView.h"

#include "shared/MeshChooser.h"
#include "shared/RenderService.h"
#include "shared/StartDialog.h"

#include <QComboBox>
#include <QFileInfo>
#include <QMouseEvent>
#include <QPainter>
#include <QPolygonF>
#include <QSettings>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace marbler::ui {

SolidObjectView::SolidObjectView(RenderService* renderer, QWidget* parent)
    : QWidget(parent)
    , mRenderer(renderer)
    , mKey(renderer->newKey()) {
    setMinimumSize(200, 200);
    setToolTip(tr("The design on its object: drag to turn it"));
    connect(mRenderer, &RenderService::rendered, this, [this](std::uint64_t key, const QImage& image, bool) {
        if (key != mKey) return;
        mImage = image;
        mMessage.clear();
        update();
    });
    connect(mRenderer, &RenderService::failed, this, [this](std::uint64_t key, const QString& message) {
        if (key != mKey) return;
        mImage = QImage();
        mMessage = tr("Cannot show the design on this object: %1").arg(message);
        update();
    });
}

void SolidObjectView::offerObjects() {
    if (mObjects) return;
    mObjects = new QComboBox(this);
    mObjects->setObjectName(QStringLiteral("objectPreviewMesh"));
    mObjects->setToolTip(tr("The object the flat design is shown on, laid on its texture coordinates"));
    for (const QString& name : meshNames())
        mObjects->addItem(name, name);
    const QString remembered =
        QSettings().value(QStringLiteral("editor/flatMesh"), QStringLiteral("book")).toString();
    const bool known = meshNames().contains(remembered) || QFileInfo(remembered).isFile();
    mMesh = known ? remembered : QStringLiteral("book");
    if (mObjects->findData(mMesh) < 0) mObjects->addItem(QFileInfo(mMesh).fileName(), mMesh);
    mObjects->addItem(tr("Mesh file…"), QString());
    mObjects->setCurrentIndex(mObjects->findData(mMesh));
    mObjects->move(6, 6);
    mObjects->adjustSize();
    connect(mObjects, &QComboBox::activated, this, [this](int index) {
        QString mesh = mObjects->itemData(index).toString();
        if (mesh.isEmpty()) {
            mesh = chooseMeshFile(window());
            const QString problem = mesh.isEmpty() ? QString() : meshFileProblem(mesh);
            if (mesh.isEmpty() || !problem.isEmpty()) {
                mObjects->setCurrentIndex(std::max(0, mObjects->findData(mMesh)));
                if (!problem.isEmpty()) {
                    mMessage = problem;
                    mImage = QImage();
                    update();
                }
                return;
            }
            mesh = QFileInfo(mesh).absoluteFilePath();
            if (mObjects->findData(mesh) < 0)
                mObjects->insertItem(mObjects->count() - 1, QFileInfo(mesh).fileName(), mesh);
            mObjects->setCurrentIndex(mObjects->findData(mesh));
        }
        QSettings().setValue(QStringLiteral("editor/flatMesh"), mesh);
        setMesh(mesh);
    });
}

SolidObjectView::~SolidObjectView() {
    mRenderer->cancel(mKey);
}

void SolidObjectView::setDesign(const Genome& design) {
    // The design's own angle at first; after that the angle the user turned it to.
    if (!mAngleSet) mAngle = viewAngleOf(design);
    mAngleSet = true;
    mDesign = design;
    request(false);
}

void SolidObjectView::setSlice(const Slice& slice) {
    mSlice = slice;
    setToolTip(tr("The design on its object: drag to turn it; drag the block in the corner to turn the "
                  "cross-section"));
    update();
}

void SolidObjectView::setMesh(const QString& mesh) {
    mMesh = mesh;
    request(false);
}

void SolidObjectView::request(bool previewOnly) {
    if (!mAngleSet || width() < 8 || height() < 8) return;
    // A flat design's preview is optional: no render while it is hidden.
    if (mDesign.dimension != 3 && !isVisible()) return;
    RenderRequest r;
    r.genome = mDesign;
    setViewAngle(r.genome, mAngle);
    const qreal dpr = devicePixelRatioF();
    const int side = int(std::min(width(), height()) * dpr);
    r.size = QSize(side, side);
    r.mesh = mMesh;
    r.flatOnObject = mDesign.dimension != 3;
    r.yaw = mAngle.yaw;
    r.pitch = mAngle.pitch;
    r.previewOnly = previewOnly;
    mRenderer->request(mKey, std::move(r));
}

void SolidObjectView::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), palette().window());
    if (mImage.isNull()) {
        p.drawText(rect().adjusted(8, 40, -8, -8), Qt::AlignCenter | Qt::TextWordWrap,
                   mMessage.isEmpty() ? tr("Rendering…") : mMessage);
        return;
    }
    QSizeF size = QSizeF(mImage.size()) / devicePixelRatioF();
    size.scale(QSizeF(this->size()), Qt::KeepAspectRatio);
    const QRectF target((width() - size.width()) / 2, (height() - size.height()) / 2, size.width(),
                        size.height());
    p.setRenderHint(QPainter::SmoothPixmapTransform);
    p.drawImage(target, mImage);
    if (mSlice && mDesign.dimension == 3) paintSlice(p);
}

void SolidObjectView::paintSlice(QPainter& p) const {
    // The block in an oblique view in the corner, the section a plane through it: where the
    // canvas cuts, at a glance, whatever the object's shape.
    const glm::dvec3 size = mDesign.size;
    const double extent = std::max({size.x, size.y, size.z, 1e-9});
    constexpr double Side = 64.0;
    const QPointF origin(12.0, height() - 14.0);
    const auto at = [&](glm::dvec3 q) {
        q /= extent;
        return origin + QPointF((q.x + 0.5 * q.z) * Side, -(q.y + 0.35 * q.z) * Side);
    };
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(30, 30, 30, 200));
    p.drawRoundedRect(sliceInset(), 6.0, 6.0);
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(QColor(220, 220, 220, 200), 1.0));
    const glm::dvec3 corner[8] = {
        {0, 0, 0},      {size.x, 0, 0},      {size.x, size.y, 0},      {0, size.y, 0},
        {0, 0, size.z}, {size.x, 0, size.z}, {size.x, size.y, size.z}, {0, size.y, size.z}};
    constexpr int Edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                  {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    for (const auto& e : Edges)
        p.drawLine(at(corner[e[0]]), at(corner[e[1]]));
    // The plane: where it cuts the block's edges, in order round it (a turned section's cut is a
    // polygon of three to six corners; an axis section's, the block's extent at its value).
    const SlicePlane section = slicePlane(3, *mSlice, size);
    const glm::dvec3 n = section.normal();
    const auto above = [&](const glm::dvec3& q) { return glm::dot(q, n) - section.value; };
    std::vector<glm::dvec2> cut;
    for (const auto& e : Edges) {
        const double a = above(corner[e[0]]), b = above(corner[e[1]]);
        if ((a < 0.0) == (b < 0.0) && a != 0.0) continue;
        const double t = a == b ? 0.0 : a / (a - b);
        cut.push_back(section.toPlane(corner[e[0]] + t * (corner[e[1]] - corner[e[0]])));
    }
    glm::dvec2 middle(0.0);
    for (const glm::dvec2& q : cut)
        middle += q / double(std::max<std::size_t>(cut.size(), 1));
    std::sort(cut.begin(), cut.end(), [&](const glm::dvec2& a, const glm::dvec2& b) {
        return std::atan2(a.y - middle.y, a.x - middle.x) < std::atan2(b.y - middle.y, b.x - middle.x);
    });
    QPolygonF plane;
    for (const glm::dvec2& q : cut)
        plane << at(section.fromPlane(q));
    p.setPen(QPen(QColor(255, 170, 40), 1.5));
    p.setBrush(QColor(255, 170, 40, 90));
    p.drawPolygon(plane);
    p.setPen(QColor(235, 235, 235));
    p.drawText(
        QPointF(origin.x() + Side * 1.55, origin.y() - 2.0),
        section.turned
            ? tr("n·p = %1").arg(section.value, 0, 'f', 1)
            : tr("%1 = %2").arg(QLatin1String(axisName(section.normalAxis))).arg(section.value, 0, 'f', 1));
}

void SolidObjectView::resizeEvent(QResizeEvent*) {
    request(false);
}

void SolidObjectView::showEvent(QShowEvent*) {
    if (mDesign.dimension != 3) request(false);
}

// ---- Issue 23: the section turned by dragging its plane in the corner ----
QRectF SolidObjectView::sliceInset() const {
    // As paintSlice draws it: the block's oblique view, 64 pixels a side, in the bottom left.
    constexpr double Side = 64.0;
    const QPointF origin(12.0, height() - 14.0);
    return QRectF(origin.x() - 8.0, origin.y() - Side * 1.5, Side * 2.9, Side * 1.5 + 8.0);
}

namespace {
/// Radians a pixel of drag in the corner turns the section's normal.
constexpr double SliceTurnPerPixel = 0.01;
} // namespace

void SolidObjectView::mousePressEvent(QMouseEvent* event) {
    mLast = event->position();
    if (mSlice && mDesign.dimension == 3 && sliceInset().contains(event->position())) {
        mTurningSlice = true;
        return;
    }
    mTurning = true;
}

void SolidObjectView::mouseMoveEvent(QMouseEvent* event) {
    const QPointF d = event->position() - mLast;
    if (mTurningSlice) {
        mLast = event->position();
        // The normal's tip follows the drag in the corner's view: right about y, down about x.
        const SlicePlane plane = slicePlane(3, *mSlice, mDesign.size);
        glm::dvec3 n = plane.normal();
        const double a = SliceTurnPerPixel * d.x(), b = SliceTurnPerPixel * d.y();
        n = {n.x * std::cos(a) + n.z * std::sin(a), n.y, -n.x * std::sin(a) + n.z * std::cos(a)};
        n = {n.x, n.y * std::cos(b) - n.z * std::sin(b), n.y * std::sin(b) + n.z * std::cos(b)};
        n = glm::normalize(n);
        // Through the old plane's point nearest the block's middle, kept within the block.
        const glm::dvec3 middle = 0.5 * mDesign.size;
        const glm::dvec3 kept = middle - (glm::dot(plane.normal(), middle) - plane.value) * plane.normal();
        const glm::dvec2 range = sliceOffsetRange(n, mDesign.size);
        int nearest = 0;
        for (int i = 1; i < 3; ++i)
            if (std::abs(n[i]) > std::abs(n[nearest])) nearest = i;
        Slice turned{nearest, std::clamp(glm::dot(n, kept), range.x, range.y), n};
        const SlicePlane onAxis = slicePlane(3, turned, mDesign.size);
        if (!onAxis.turned) turned = Slice{onAxis.normalAxis, onAxis.value};
        emit sliceTurned(turned);
        return;
    }
    if (!mTurning) return;
    mLast = event->position();
    mAngle = mAngle.dragged(d.x(), d.y());
    request(true);
}

void SolidObjectView::mouseReleaseEvent(QMouseEvent*) {
    if (std::exchange(mTurningSlice, false)) return;
    if (!mTurning) return;
    mTurning = false;
    request(false);
}
// ---- end issue 23 ----

} // namespace marbler::ui
