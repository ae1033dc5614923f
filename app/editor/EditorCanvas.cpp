#include "editor/EditorCanvas.h"

#include "marbler/Params.h"
#include "marbler/Tools.h"

#include <QFontMetricsF>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QWheelEvent>

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>

namespace marbler::ui {

namespace {

/// How near (widget pixels) a press must come to a handle to take it.
constexpr double HandleReach = 9.0;
/// The length (widget pixels) of a direction handle's arm.
constexpr double ArmLength = 70.0;

/// A flat step has a direction handle where its tool's 2D parameters have an angle (registry).
bool hasAngle(Tool tool) {
    const auto params = toolSpec(tool).params2D;
    return std::any_of(params.begin(), params.end(),
                       [](const ParamSpec& p) { return p.field == ParamField::Angle; });
}
/// A radius handle where the tool has a radius, in either dimension (registry).
bool hasRadius(Tool tool) {
    return findParam(tool, ParamField::Radius) != nullptr;
}

} // namespace

EditorCanvas::EditorCanvas(RenderService* renderer, QWidget* parent)
    : QWidget(parent)
    , mRenderer(renderer)
    , mKey(renderer->newKey()) {
    setObjectName(QStringLiteral("editorCanvas"));
    setMinimumSize(240, 240);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(false);
    setToolTip(
        tr("Drag with the current tool; middle or right drag (or Space and drag) pans, the wheel zooms, "
           "0 fits, 1 shows one to one"));
    connect(mRenderer, &RenderService::rendered, this, &EditorCanvas::onRendered);
    mSlice = Slice{2, mDesign.size.z / 2.0};
    updateDesignSize();
    setTool(mTool);
}

EditorCanvas::~EditorCanvas() {
    mRenderer->cancel(mKey);
}

void EditorCanvas::setDesign(const Genome& rendered) {
    const bool resized = rendered.size != mDesign.size || rendered.dimension != mDesign.dimension;
    mDesign = rendered;
    if (resized) {
        if (mDesign.dimension == 3 && !mSliceChosen) mSlice = Slice{2, mDesign.size.z / 2.0};
        updateDesignSize();
    }
    if (mHandles && *mHandles >= mDesign.initial.size() + mDesign.operations.size()) mHandles.reset();
    rerender();
}

void EditorCanvas::setDragging(bool on) {
    if (mDragging == on) return;
    mDragging = on;
    if (!on) rerender();
}

void EditorCanvas::setTool(EditorTool tool) {
    mTool = tool;
    setCursor(tool == EditorTool::Pick ? Qt::PointingHandCursor : Qt::CrossCursor);
}

void EditorCanvas::setToolSettings(const ToolSettings& settings) {
    mSettings = settings;
}

void EditorCanvas::setHandlesFor(std::optional<std::size_t> renderedIndex) {
    mHandles = renderedIndex;
    update();
}

void EditorCanvas::setSlice(const Slice& slice) {
    mSlice = slice;
    mSliceChosen = true;
    updateDesignSize();
    rerender();
}

QSizeF EditorCanvas::planeSize() const {
    const glm::dvec2 extent = slicePlane(mDesign.dimension, mSlice.axis).extent(mDesign.size);
    return {extent.x, extent.y};
}

void EditorCanvas::updateDesignSize() {
    const QSizeF plane = planeSize();
    mView.setDesignSize(plane.width(), plane.height());
    mView.setViewport((size() * devicePixelRatioF()).expandedTo(QSize(1, 1)));
}

QPointF EditorCanvas::toPlane(const glm::dvec3& p) const {
    const glm::dvec2 q = slicePlane(mDesign.dimension, mSlice.axis).toPlane(p);
    return {q.x, q.y};
}

glm::dvec3 EditorCanvas::fromPlane(QPointF q) const {
    return slicePlane(mDesign.dimension, mSlice.axis, mSlice.value).fromPlane({q.x(), q.y()});
}

glm::dvec3 EditorCanvas::toDesign(QPointF widgetPoint) const {
    return fromPlane(mView.toDesign(widgetPoint * devicePixelRatioF()));
}

QPointF EditorCanvas::toWidget(const glm::dvec3& designPoint) const {
    return mView.toViewport(toPlane(designPoint)) / devicePixelRatioF();
}

void EditorCanvas::rerender() {
    if (mDrag == Drag::Gesture && !mPending.empty())
        requestRender(withSteps(mDesign, mPending), true);
    else
        requestRender(mDesign, mDragging || mDrag == Drag::Handle);
}

void EditorCanvas::requestRender(const Genome& genome, bool previewOnly) {
    auto window = mView.visibleWindow();
    if (mRepeat != RepeatPreview::Off && genome.size.x > 0) {
        // Any tile may show any part of the design: render all of it, at the view's scale (at
        // most 1024 pixels a side; the tiles are for judging seams, not detail).
        const QSizeF plane = planeSize();
        const double scale = std::min(mView.scale(), 1024.0 / std::max(plane.width(), plane.height()));
        ViewController::Window whole;
        whole.region = Region{0.0, 0.0, plane.width(), plane.height()};
        whole.pixels = QRect(0, 0, std::max(1, int(std::lround(plane.width() * scale))),
                             std::max(1, int(std::lround(plane.height() * scale))));
        window = whole;
    }
    if (!window || genome.size.x <= 0) {
        mRenderer->cancel(mKey);
        mShown.image = QImage();
        update();
        return;
    }
    RenderRequest request;
    request.genome = genome;
    request.region = window->region;
    request.size = window->pixels.size();
    request.previewOnly = previewOnly;
    if (genome.dimension == 3) request.slice = mSlice;
    mShown.requested = request.region;
    mShown.final = false;
    mRenderer->request(mKey, std::move(request));
}

void EditorCanvas::onRendered(std::uint64_t key, const QImage& image, bool final) {
    if (key != mKey) return;
    mShown.image = image;
    if (mShown.requested) mShown.region = *mShown.requested;
    // A preview-only request's single pass comes as final, but it is still the coarse one.
    mShown.final = final && !mDragging && mDrag == Drag::None;
    update();
}

void EditorCanvas::changeView() {
    update(); // the image so far, moved and scaled at once, until the new render comes
    rerender();
}

void EditorCanvas::fitView() {
    mView.fit();
    // The repeat preview's nine tiles, the design in the middle.
    if (mRepeat != RepeatPreview::Off)
        mView.zoomBy(1.0 / 3.0, QRectF(QPointF(0, 0), QSizeF(mView.viewport())).center());
    changeView();
}

void EditorCanvas::setCaption(const QString& text) {
    if (text == mCaption) return;
    mCaption = text;
    update();
}

void EditorCanvas::setRepeatPreview(RepeatPreview mode) {
    if (mode == mRepeat) return;
    mRepeat = mode;
    fitView();
}

void EditorCanvas::oneToOne() {
    mView.oneToOne();
    changeView();
}
void EditorCanvas::zoomIn() {
    mView.zoomBy(std::sqrt(2.0), QRectF(QPointF(0, 0), QSizeF(mView.viewport())).center());
    changeView();
}
void EditorCanvas::zoomOut() {
    mView.zoomBy(1.0 / std::sqrt(2.0), QRectF(QPointF(0, 0), QSizeF(mView.viewport())).center());
    changeView();
}

void EditorCanvas::resizeEvent(QResizeEvent*) {
    mView.setViewport((size() * devicePixelRatioF()).expandedTo(QSize(1, 1)));
    rerender();
}

void EditorCanvas::wheelEvent(QWheelEvent* event) {
    const double notches = event->angleDelta().y() / 120.0;
    if (notches != 0.0) {
        mView.zoomBy(std::pow(std::sqrt(2.0), notches), event->position() * devicePixelRatioF());
        changeView();
    }
    event->accept();
}

void EditorCanvas::keyPressEvent(QKeyEvent* event) {
    if (ViewController::handleKey(event, {[this] { zoomIn(); }, [this] { zoomOut(); }, [this] { fitView(); },
                                          [this] { oneToOne(); }}))
        return;
    if (event->key() == Qt::Key_Space) {
        if (!event->isAutoRepeat()) mSpace = true;
        setCursor(Qt::OpenHandCursor);
        return;
    }
    QWidget::keyPressEvent(event);
}

void EditorCanvas::keyReleaseEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Space && !event->isAutoRepeat()) {
        mSpace = false;
        setTool(mTool);
        return;
    }
    QWidget::keyReleaseEvent(event);
}

std::optional<Operation> EditorCanvas::selectedStep() const {
    if (!mHandles) return std::nullopt;
    const std::size_t i = *mHandles;
    if (i < mDesign.initial.size()) return mDesign.initial[i];
    if (i - mDesign.initial.size() < mDesign.operations.size())
        return mDesign.operations[i - mDesign.initial.size()];
    return std::nullopt;
}

std::vector<std::pair<EditorCanvas::Handle, QPointF>> EditorCanvas::handlePoints() const {
    std::vector<std::pair<Handle, QPointF>> points;
    const std::optional<Operation> op = selectedStep();
    if (!op) return points;
    const QPointF centre = toWidget(op->center);
    points.emplace_back(Handle::Centre, centre);
    if (mDesign.dimension != 3 && hasAngle(op->tool)) {
        const double a = op->angle * std::numbers::pi / 180.0;
        points.emplace_back(Handle::Direction, centre + ArmLength * QPointF(std::cos(a), std::sin(a)));
    }
    if (hasRadius(op->tool)) {
        const QPointF plane = toPlane(op->center) + QPointF(op->radius, 0.0);
        points.emplace_back(Handle::Radius, mView.toViewport(plane) / devicePixelRatioF());
    }
    return points;
}

Operation EditorCanvas::movedStep(Handle handle, QPointF widget) const {
    Operation op = *selectedStep();
    const glm::dvec3 at = toDesign(widget);
    switch (handle) {
    case Handle::Centre: {
        // Only the plane's two coordinates move; a solid's step keeps its depth.
        const QPointF plane = toPlane(at);
        const QPointF was = toPlane(op.center);
        const glm::dvec3 shifted = fromPlane(plane) - fromPlane(was);
        op.center += mDesign.dimension == 3 ? shifted : glm::dvec3(shifted.x, shifted.y, 0.0);
        break;
    }
    case Handle::Direction: {
        const QPointF d = widget - toWidget(op.center);
        if (std::hypot(d.x(), d.y()) > 1.0) op.angle = std::atan2(d.y(), d.x()) * 180.0 / std::numbers::pi;
        break;
    }
    case Handle::Radius: {
        const QPointF d = toPlane(at) - toPlane(op.center);
        op.radius = std::max(std::hypot(d.x(), d.y()), 1e-3);
        break;
    }
    }
    return op;
}

void EditorCanvas::mousePressEvent(QMouseEvent* event) {
    mLastPos = event->position();
    const bool left = event->button() == Qt::LeftButton;
    if (event->button() == Qt::MiddleButton || event->button() == Qt::RightButton || (left && mSpace)) {
        mDrag = Drag::Pan;
        setCursor(Qt::ClosedHandCursor);
        return;
    }
    if (!left) return;
    for (const auto& [handle, point] : handlePoints()) {
        const QPointF d = point - event->position();
        if (std::hypot(d.x(), d.y()) <= HandleReach) {
            mDrag = Drag::Handle;
            mHandle = handle;
            return;
        }
    }
    if (mTool == EditorTool::Pick) {
        const TracedInk ink = traceStep(prepare(mDesign), toDesign(event->position()));
        emit inkPicked(ink.color,
                       ink.step >= 0 ? std::optional<std::size_t>(std::size_t(ink.step)) : std::nullopt);
        return;
    }
    if (!toolAvailable(mTool, mDesign.dimension)) return;
    mDrag = Drag::Gesture;
    mPress = mCurrent = toDesign(event->position());
    mPending = gestureSteps(mTool, mSettings, mPress, mCurrent, mDesign, mSlice.axis);
    rerender();
    update();
}

void EditorCanvas::mouseMoveEvent(QMouseEvent* event) {
    const QPointF delta = event->position() - mLastPos;
    mLastPos = event->position();
    switch (mDrag) {
    case Drag::None:
        return;
    case Drag::Pan:
        mView.panBy(delta * devicePixelRatioF());
        update();
        requestRender(mDesign, true);
        return;
    case Drag::Handle: {
        // The step may have gone under the drag (an undo, a delete, the timeline playing).
        if (!selectedStep()) {
            mDrag = Drag::None;
            return;
        }
        const Operation op = movedStep(mHandle, event->position());
        requestRender(withReplaced(op), true);
        update();
        emit handleDragged(*mHandles, op, false);
        return;
    }
    case Drag::Gesture:
        mCurrent = toDesign(event->position());
        mPending = gestureSteps(mTool, mSettings, mPress, mCurrent, mDesign, mSlice.axis);
        rerender();
        update();
        return;
    }
}

void EditorCanvas::mouseReleaseEvent(QMouseEvent* event) {
    const Drag drag = std::exchange(mDrag, Drag::None);
    switch (drag) {
    case Drag::None:
        return;
    case Drag::Pan:
        setTool(mTool);
        rerender();
        return;
    case Drag::Handle: {
        if (!selectedStep()) return;
        const Operation op = movedStep(mHandle, event->position());
        requestRender(withReplaced(op), mDragging);
        emit handleDragged(*mHandles, op, true);
        return;
    }
    case Drag::Gesture: {
        mCurrent = toDesign(event->position());
        std::vector<Operation> ops = gestureSteps(mTool, mSettings, mPress, mCurrent, mDesign, mSlice.axis);
        mPending.clear();
        if (ops.empty()) {
            rerender();
            update();
            return;
        }
        // Drawn with the new steps until the window hands the changed design back.
        requestRender(withSteps(mDesign, ops), mDragging);
        update();
        const QString name = QString::fromUtf8(toolSpec(ops.front().tool).name.data(),
                                               qsizetype(toolSpec(ops.front().tool).name.size()));
        const QString text = ops.size() == 1 ? name : tr("%1 %2s").arg(ops.size()).arg(name);
        emit stepsMade(ops, text);
        return;
    }
    }
}

Genome EditorCanvas::withReplaced(const Operation& op) const {
    Genome genome = mDesign;
    if (!mHandles) return genome;
    const std::size_t i = *mHandles;
    if (i < genome.initial.size())
        genome.initial[i] = op;
    else if (i - genome.initial.size() < genome.operations.size())
        genome.operations[i - genome.initial.size()] = op;
    return genome;
}

void EditorCanvas::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), palette().color(QPalette::Window).darker(115));
    if (!mShown.image.isNull()) {
        const QRectF r = mView.toViewport(mShown.region);
        const double ratio = devicePixelRatioF();
        p.setRenderHint(QPainter::SmoothPixmapTransform);
        if (mRepeat == RepeatPreview::Off) {
            p.drawImage(QRectF(r.topLeft() / ratio, r.size() / ratio), mShown.image);
        } else {
            const QSizeF plane = planeSize();
            for (int j = -1; j <= 1; ++j)
                for (int i = -1; i <= 1; ++i) {
                    const Region tile{i * plane.width(), j * plane.height(), (i + 1) * plane.width(),
                                      (j + 1) * plane.height()};
                    const QRectF t = mView.toViewport(tile);
                    const bool mirror = mRepeat == RepeatPreview::Mirror;
                    p.drawImage(QRectF(t.topLeft() / ratio, t.size() / ratio),
                                mirror && (i != 0 || j != 0) ? mShown.image.mirrored(i != 0, j != 0)
                                                             : mShown.image);
                }
        }
    }
    drawOverlay(p);
    drawCaption(p);
}

void EditorCanvas::drawCaption(QPainter& p) const {
    if (mCaption.isEmpty()) return;
    QFont font = p.font();
    font.setBold(true);
    p.setFont(font);
    const QFontMetricsF metrics(font);
    const QRectF text = metrics.boundingRect(mCaption).translated(12.0, 10.0 + metrics.ascent());
    const QRectF box = text.adjusted(-6, -3, 6, 3);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0, 0, 0, 170));
    p.drawRoundedRect(box, 4, 4);
    p.setPen(QColor(255, 255, 255));
    p.drawText(box, Qt::AlignCenter, mCaption);
}

void EditorCanvas::drawStepOutline(QPainter& painter, const Operation& op) const {
    const QPointF c = toWidget(op.center);
    const double scale = mView.scale() / devicePixelRatioF(); // widget pixels a design unit
    switch (toolSpec(op.tool).outline) {
    case StepOutline::Radius: {
        const double r = op.radius * scale;
        painter.drawEllipse(c, r, r);
        break;
    }
    case StepOutline::Alpha: {
        const double r = std::abs(op.alpha) * scale;
        painter.drawEllipse(c, r, r);
        break;
    }
    case StepOutline::Extent:
        painter.drawRect(QRectF(c, QSizeF(op.extent.x * scale, op.extent.y * scale)));
        break;
    case StepOutline::None:
        break; // strokes across the whole design: the handles say enough
    }
}

void EditorCanvas::drawOverlay(QPainter& p) const {
    p.setRenderHint(QPainter::Antialiasing);
    // Dark under light: seen on any ink.
    const QPen dark(QColor(0, 0, 0, 160), 3.0), light(QColor(255, 255, 255, 230), 1.5);
    if (mDrag == Drag::Gesture) {
        for (const QPen& pen : {dark, light}) {
            p.setPen(pen);
            p.setBrush(Qt::NoBrush);
            const QPointF a = toWidget(mPress), b = toWidget(mCurrent);
            if (a != b) p.drawLine(a, b);
            for (const Operation& op : mPending)
                drawStepOutline(p, op);
        }
    }
    const auto handles = handlePoints();
    if (const std::optional<Operation> op = selectedStep(); op && !handles.empty()) {
        for (const QPen& pen : {dark, light}) {
            p.setPen(pen);
            p.setBrush(Qt::NoBrush);
            drawStepOutline(p, mDrag == Drag::Handle ? movedStep(mHandle, mLastPos) : *op);
            for (const auto& [handle, point] : handles)
                if (handle == Handle::Direction) p.drawLine(handles.front().second, point);
        }
        p.setPen(dark);
        for (const auto& [handle, point] : handles) {
            p.setBrush(handle == Handle::Centre ? QColor(255, 255, 255) : QColor(255, 200, 60));
            p.drawEllipse(point, 5.0, 5.0);
        }
    }
}

} // namespace marbler::ui
