#include "editor/EditorCanvas.h"

#include "marbler/Params.h"
#include "marbler/Tools.h"

#include <QFontMetricsF>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QPolygonF>
#include <QTabletEvent>
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
/// A handle on each point where the tool has a path (registry): a stylus.
bool hasPath(Tool tool) {
    return findParam(tool, ParamField::Path) != nullptr;
}

// ---- Issue 23: a solid stroke's direction handle ----
/// A solid's stroke (line, comb, wave) has a direction handle where its tool's 3D parameters
/// have a direction (registry). The handle points the way the stroke moves ink: `direction`,
/// but a wave's shift is its `normal` (the wave gesture drags along that).
bool hasSolidDirection(Tool tool) {
    const auto params = toolSpec(tool).params3D;
    return std::any_of(params.begin(), params.end(),
                       [](const ParamSpec& p) { return p.field == ParamField::Direction; });
}
glm::dvec3& solidMotion(Operation& op) {
    return toolSpec(op.tool).editor.gesture == EditorGesture::Wave ? op.normal : op.direction;
}
glm::dvec3& solidAcross(Operation& op) {
    return toolSpec(op.tool).editor.gesture == EditorGesture::Wave ? op.direction : op.normal;
}
/// `w` turned by the angle (cosine c, sine s) about the unit `n`.
glm::dvec3 turnedAbout(const glm::dvec3& w, const glm::dvec3& n, double c, double s) {
    const glm::dvec3 along = glm::dot(w, n) * n, flat = w - along;
    return along + c * flat + s * glm::cross(n, flat);
}
// ---- end issue 23 ----

/// How long a free-hand stroke's live preview may take (ms): 25 a second, with room to spare.
constexpr double PreviewTargetMs = 35.0;
/// The smallest fraction of the view's pixels such a preview is rendered at.
constexpr double MinPreviewScale = 0.08;

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
        tr("Drag with the current tool (Esc drops the drag); middle or right drag (or Space and drag) pans, "
           "the wheel zooms, 0 fits, 1 shows one to one"));
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
    const glm::dvec2 extent = slicePlane(mDesign.dimension, mSlice, mDesign.size).extent(mDesign.size);
    return {extent.x, extent.y};
}

void EditorCanvas::updateDesignSize() {
    const QSizeF plane = planeSize();
    mView.setDesignSize(plane.width(), plane.height());
    mView.setViewport((size() * devicePixelRatioF()).expandedTo(QSize(1, 1)));
}

QPointF EditorCanvas::toPlane(const glm::dvec3& p) const {
    const glm::dvec2 q = slicePlane(mDesign.dimension, mSlice, mDesign.size).toPlane(p);
    return {q.x, q.y};
}

glm::dvec3 EditorCanvas::fromPlane(QPointF q) const {
    return slicePlane(mDesign.dimension, mSlice, mDesign.size).fromPlane({q.x(), q.y()});
}

glm::dvec3 EditorCanvas::toDesign(QPointF widgetPoint) const {
    return fromPlane(mView.toDesign(widgetPoint * devicePixelRatioF()));
}

QPointF EditorCanvas::toWidget(const glm::dvec3& designPoint) const {
    return mView.toViewport(toPlane(designPoint)) / devicePixelRatioF();
}

void EditorCanvas::rerender() {
    // A stroke being drawn, or a path point being moved: the stroke as it is now, once the render
    // in flight has come (see mPreviewInFlight).
    const std::optional<Operation> selected = mDrag == Drag::Handle ? selectedStep() : std::nullopt;
    const bool stroke = mDrag == Drag::Gesture && !mPending.empty() && drawsPath();
    if (stroke || (selected && hasPath(selected->tool))) {
        if (mPreviewInFlight) {
            mPreviewDirty = true;
            return;
        }
        mPreviewInFlight = true;
        mPreviewDirty = false;
        mPreviewClock.start();
        requestRender(stroke ? withSteps(mDesign, mPending) : withReplaced(movedStep(mHandle, mLastPos)),
                      true, mPreviewScale);
        return;
    }
    if (mDrag == Drag::Gesture && !mPending.empty()) {
        requestRender(withSteps(mDesign, mPending), true);
    } else {
        requestRender(mDesign, mDragging || mDrag == Drag::Handle);
    }
}

bool EditorCanvas::drawsPath() const {
    return gestureOf(mTool) == EditorGesture::Path && mDesign.dimension == 2;
}

void EditorCanvas::requestRender(const Genome& genome, bool previewOnly, double scale) {
    auto window = mView.visibleWindow();
    if (mRepeat != RepeatPreview::Off && genome.size.x > 0) {
        // Any tile may show any part of the design: render all of it, at the view's scale (at
        // most 1024 pixels a side; the tiles are for judging seams, not detail).
        const QSizeF plane = planeSize();
        // A bath that wraps (issue 29): the plane three tiles a side about the design, which the
        // renderer fills with the design repeated on its own lattice (straight, half-drop or
        // brick), where copies of the tile would fall between pixels.
        const int tiles = tilesByLattice() ? 3 : 1;
        const double scale =
            std::min(mView.scale(), 1024.0 / (tiles * std::max(plane.width(), plane.height())));
        const double origin = tiles == 3 ? -1.0 : 0.0;
        ViewController::Window whole;
        whole.region = Region{origin * plane.width(), origin * plane.height(),
                              (origin + tiles) * plane.width(), (origin + tiles) * plane.height()};
        // Whole pixels a tile, so its copies fall on the same pixels.
        whole.pixels = QRect(0, 0, tiles * std::max(1, int(std::lround(plane.width() * scale))),
                             tiles * std::max(1, int(std::lround(plane.height() * scale))));
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
    if (scale < 1.0) {
        // The same region in fewer pixels, its proportions kept.
        const QSize full = request.size;
        request.size = QSize(std::max(8, int(std::lround(full.width() * scale))),
                             std::max(8, int(std::lround(full.height() * scale))));
    }
    request.previewOnly = previewOnly;
    if (genome.dimension == 3) request.slice = mSlice;
    mShown.requested = request.region;
    mShown.final = false;
    mRenderer->request(mKey, std::move(request));
}

void EditorCanvas::onRendered(std::uint64_t key, const QImage& image, bool final) {
    if (key != mKey) return;
    if (std::exchange(mPreviewInFlight, false)) {
        // Fewer pixels when the last preview took too long, more when it was quick (the time
        // goes with the pixels: their square root scales the side), a step at a time.
        const double ms = std::max(1.0, double(mPreviewClock.elapsed()));
        const double factor = std::clamp(std::sqrt(PreviewTargetMs / ms), 0.5, 1.25);
        mPreviewScale = std::clamp(mPreviewScale * factor, MinPreviewScale, 1.0);
    }
    mShown.image = image;
    if (mShown.requested) mShown.region = *mShown.requested;
    // A preview-only request's single pass comes as final, but it is still the coarse one.
    mShown.final = final && !mDragging && mDrag == Drag::None;
    update();
    if (std::exchange(mPreviewDirty, false) && (mDrag == Drag::Gesture || mDrag == Drag::Handle)) rerender();
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

bool EditorCanvas::tilesByLattice() const {
    return mRepeat == RepeatPreview::Plain && mDesign.wrap && mDesign.dimension == 2;
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
    if (event->key() == Qt::Key_Escape && mDrag == Drag::Gesture) {
        // The gesture in progress is dropped: nothing is made, the design shows as it was.
        mDrag = Drag::None;
        mPenDown = false;
        mPending.clear();
        mStroke.clear();
        mStrokePressure.clear();
        mPreviewInFlight = mPreviewDirty = false;
        rerender();
        update();
        return;
    }
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
    if (hasPath(op->tool)) {
        // A stylus is its path: each point a handle, nothing else.
        points.clear();
        for (const glm::dvec2& p : op->path)
            points.emplace_back(Handle::PathPoint, toWidget({p.x, p.y, 0.0}));
        return points;
    }
    if (hasRadius(op->tool)) {
        const QPointF plane = toPlane(op->center) + QPointF(op->radius, 0.0);
        points.emplace_back(Handle::Radius, mView.toViewport(plane) / devicePixelRatioF());
    }
    if (mDesign.dimension == 3 && hasSolidDirection(op->tool)) {
        // Issue 23: the way the stroke moves ink, as it lies in the section (a whole arm out).
        Operation step = *op;
        const SlicePlane plane = slicePlane(3, mSlice, mDesign.size);
        const glm::dvec3 motion = solidMotion(step);
        const glm::dvec3 lean = motion - glm::dot(motion, plane.normal()) * plane.normal();
        const glm::dvec3 way = glm::length(lean) > 1e-9 ? lean / glm::length(lean) : -plane.v();
        const QPointF d = toWidget(op->center + way) - centre;
        const double length = std::hypot(d.x(), d.y());
        if (length > 0.0) points.emplace_back(Handle::Direction, centre + ArmLength * d / length);
    }
    if (mDesign.dimension == 3 && findParam(op->tool, ParamField::Axis)) {
        // The axis's lean out of the section, along the way it leans: sin(tilt) from half an arm
        // (across the section) to an arm and a half (lying in it).
        const SlicePlane plane = slicePlane(3, mSlice, mDesign.size);
        const glm::dvec2 lean{glm::dot(op->axis, plane.u()), glm::dot(op->axis, plane.v())};
        const double sine = std::min(glm::length(lean), 1.0);
        const glm::dvec2 way = sine > 1e-9 ? lean / glm::length(lean) : glm::dvec2(0.0, -1.0);
        points.emplace_back(Handle::Axis, centre + ArmLength * (0.5 + sine) * QPointF(way.x, way.y));
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
        if (std::hypot(d.x(), d.y()) <= 1.0) break;
        if (mDesign.dimension != 3) {
            op.angle = std::atan2(d.y(), d.x()) * 180.0 / std::numbers::pi;
            break;
        }
        // Issue 23: a solid stroke turned in the section, about its normal, so that the way it
        // moves ink points at the drag; both its vectors turn together and stay unit and square
        // to each other. One that moved ink across the section is laid along the drag.
        const SlicePlane plane = slicePlane(3, mSlice, mDesign.size);
        const glm::dvec3 n = plane.normal();
        glm::dvec3 want = at - op.center;
        want -= glm::dot(want, n) * n;
        if (glm::length(want) < 1e-12) break;
        want = glm::normalize(want);
        glm::dvec3& motion = solidMotion(op);
        glm::dvec3& across = solidAcross(op);
        const glm::dvec3 lean = motion - glm::dot(motion, n) * n;
        if (glm::length(lean) > 1e-9) {
            const glm::dvec3 was = glm::normalize(lean);
            const double c = glm::dot(was, want), s = glm::dot(glm::cross(was, want), n);
            motion = glm::normalize(turnedAbout(motion, n, c, s));
            across = glm::normalize(turnedAbout(across, n, c, s));
        } else {
            motion = want;
            const glm::dvec3 rest = across - glm::dot(across, want) * want;
            across = glm::length(rest) > 1e-9 ? glm::normalize(rest) : glm::normalize(glm::cross(n, want));
        }
        break;
    }
    case Handle::Radius: {
        const QPointF d = toPlane(at) - toPlane(op.center);
        op.radius = std::max(std::hypot(d.x(), d.y()), 1e-3);
        break;
    }
    case Handle::Axis: {
        // Dragged out from the centre: the axis leans the drag's way, by sin(tilt) = the distance
        // beyond half an arm; the side of the section it points to is kept.
        const QPointF d = widget - toWidget(op.center);
        const double reach = std::hypot(d.x(), d.y());
        if (reach < 1.0) break;
        const SlicePlane plane = slicePlane(3, mSlice, mDesign.size);
        const double sine = std::clamp(reach / ArmLength - 0.5, 0.0, 1.0);
        const double side = glm::dot(op.axis, plane.normal()) < 0.0 ? -1.0 : 1.0;
        const glm::dvec3 lean = (d.x() / reach) * plane.u() + (d.y() / reach) * plane.v();
        op.axis = glm::normalize(side * std::sqrt(1.0 - sine * sine) * plane.normal() + sine * lean);
        break;
    }
    case Handle::PathPoint: {
        const std::size_t i = mHandleIndex;
        if (i >= op.path.size()) break;
        Operation moved = op;
        moved.path[i] = {at.x, at.y};
        // Consecutive points stay different; the steps stay valid (the fewest still, where they
        // were the fewest), and a point that would need more than a stylus may take stays put.
        const bool apart = (i == 0 || moved.path[i] != moved.path[i - 1]) &&
                           (i + 1 == moved.path.size() || moved.path[i] != moved.path[i + 1]);
        if (!apart) break;
        const int fewest = minimumStylusSteps(moved);
        moved.steps = op.steps == minimumStylusSteps(op) ? fewest : std::max(op.steps, fewest);
        if (moved.steps <= MaxStylusSteps) op = moved;
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
    if (!left || mPenDown) return;
    // The nearest handle within reach (a path's points lie close together).
    const auto handles = handlePoints();
    double nearest = HandleReach;
    for (std::size_t i = 0; i < handles.size(); ++i) {
        const QPointF d = handles[i].second - event->position();
        const double distance = std::hypot(d.x(), d.y());
        if (distance <= HandleReach && (mDrag != Drag::Handle || distance < nearest)) {
            nearest = distance;
            mDrag = Drag::Handle;
            mHandle = handles[i].first;
            mHandleIndex = i;
        }
    }
    if (mDrag == Drag::Handle) return;
    if (mTool == EditorTool::Pick) {
        const TracedInk ink = traceStep(prepare(mDesign), toDesign(event->position()));
        emit inkPicked(ink.color,
                       ink.step >= 0 ? std::optional<std::size_t>(std::size_t(ink.step)) : std::nullopt);
        return;
    }
    beginGesture(event->position(), 1.0);
}

std::vector<Operation> EditorCanvas::gestureSoFar() const {
    if (drawsPath()) return pathSteps(mTool, mSettings, mStroke, mDesign, mStrokePressure);
    return gestureSteps(mTool, mSettings, mPress, mCurrent, mDesign,
                        slicePlane(mDesign.dimension, mSlice, mDesign.size));
}

void EditorCanvas::beginGesture(QPointF widget, double pressure) {
    if (!toolAvailable(mTool, mDesign.dimension)) return;
    mDrag = Drag::Gesture;
    mPress = mCurrent = toDesign(widget);
    mStroke.clear();
    mStrokePressure.clear();
    if (drawsPath()) {
        mStroke.push_back(mPress);
        mStrokePressure.push_back(pressure);
    }
    mPending = gestureSoFar();
    rerender();
    update();
}

void EditorCanvas::moveGesture(QPointF widget, double pressure) {
    mCurrent = toDesign(widget);
    if (drawsPath()) {
        if (mCurrent == mStroke.back()) return;
        mStroke.push_back(mCurrent);
        mStrokePressure.push_back(pressure);
    }
    mPending = gestureSoFar();
    rerender();
    update();
}

void EditorCanvas::endGesture(QPointF widget, double pressure) {
    mCurrent = toDesign(widget);
    if (drawsPath() && mCurrent != mStroke.back()) {
        mStroke.push_back(mCurrent);
        mStrokePressure.push_back(pressure);
    }
    std::vector<Operation> ops = gestureSoFar();
    const std::string refused = drawsPath() && ops.empty()
                                    ? pathRefusal(mTool, mSettings, mStroke, mDesign, mStrokePressure)
                                    : std::string();
    mPending.clear();
    mStroke.clear();
    mStrokePressure.clear();
    mPreviewInFlight = mPreviewDirty = false;
    if (ops.empty()) {
        rerender();
        update();
        if (!refused.empty()) emit gestureRefused(QString::fromStdString(refused));
        return;
    }
    // Drawn with the new steps until the window hands the changed design back.
    requestRender(withSteps(mDesign, ops), mDragging);
    update();
    const QString name = QString::fromUtf8(toolSpec(ops.front().tool).name.data(),
                                           qsizetype(toolSpec(ops.front().tool).name.size()));
    const QString text = ops.size() == 1 ? name : tr("%1 %2s").arg(ops.size()).arg(name);
    emit stepsMade(ops, text);
}

void EditorCanvas::tabletEvent(QTabletEvent* event) {
    // Only a free-hand stroke uses the pen's pressure; anything else (a pan, a handle, another
    // tool) is left to the mouse event Qt makes of an ignored tablet event.
    const double pressure = std::clamp(double(event->pressure()), 0.0, 1.0);
    switch (event->type()) {
    case QEvent::TabletPress: {
        if (!drawsPath() || mSpace || event->button() != Qt::LeftButton || mDrag != Drag::None) break;
        const auto handles = handlePoints();
        const bool onHandle = std::any_of(handles.begin(), handles.end(), [&](const auto& h) {
            const QPointF d = h.second - event->position();
            return std::hypot(d.x(), d.y()) <= HandleReach;
        });
        if (onHandle || !toolAvailable(mTool, mDesign.dimension)) break;
        mPenDown = true;
        mLastPos = event->position();
        beginGesture(event->position(), pressure);
        event->accept();
        return;
    }
    case QEvent::TabletMove:
        if (!mPenDown) break;
        mLastPos = event->position();
        if (mDrag == Drag::Gesture) moveGesture(event->position(), pressure);
        event->accept();
        return;
    case QEvent::TabletRelease:
        if (!mPenDown) break;
        mPenDown = false;
        // A pen lifts at nearly no pressure: the stroke ends as it was last drawn.
        if (std::exchange(mDrag, Drag::None) == Drag::Gesture)
            endGesture(event->position(), mStrokePressure.empty() ? pressure : mStrokePressure.back());
        event->accept();
        return;
    default:
        break;
    }
    event->ignore();
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
        if (hasPath(op.tool))
            rerender(); // a stroke's render is slow: paced as while drawing
        else
            requestRender(withReplaced(op), true);
        update();
        emit handleDragged(*mHandles, op, false);
        return;
    }
    case Drag::Gesture:
        if (!mPenDown) moveGesture(event->position(), 1.0);
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
        mPreviewInFlight = mPreviewDirty = false;
        requestRender(withReplaced(op), mDragging);
        emit handleDragged(*mHandles, op, true);
        return;
    }
    case Drag::Gesture:
        endGesture(event->position(), 1.0);
        return;
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
        // The lattice's repeat came rendered whole (requestRender); a region wider than the design
        // is that, until a new render replaces it.
        const QSizeF plane = planeSize();
        const bool rendered = mShown.region.x1 - mShown.region.x0 > 1.5 * plane.width();
        if (mRepeat == RepeatPreview::Off || rendered) {
            p.drawImage(QRectF(r.topLeft() / ratio, r.size() / ratio), mShown.image);
        } else {
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
        // A free-hand stroke's track as the pointer went, at once (the render follows).
        QPolygonF track;
        for (const glm::dvec3& at : mStroke)
            track << toWidget(at);
        for (const QPen& pen : {dark, light}) {
            p.setPen(pen);
            p.setBrush(Qt::NoBrush);
            const QPointF a = toWidget(mPress), b = toWidget(mCurrent);
            if (!mStroke.empty())
                p.drawPolyline(track);
            else if (a != b)
                p.drawLine(a, b);
            for (const Operation& op : mPending)
                drawStepOutline(p, op);
        }
    }
    const auto handles = handlePoints();
    if (const std::optional<Operation> op = selectedStep(); op && !handles.empty()) {
        const Operation shown = mDrag == Drag::Handle ? movedStep(mHandle, mLastPos) : *op;
        QPolygonF path;
        for (const glm::dvec2& at : shown.path)
            path << toWidget({at.x, at.y, 0.0});
        for (const QPen& pen : {dark, light}) {
            p.setPen(pen);
            p.setBrush(Qt::NoBrush);
            drawStepOutline(p, shown);
            if (!path.isEmpty()) p.drawPolyline(path);
            for (const auto& [handle, point] : handles)
                if (handle == Handle::Direction || handle == Handle::Axis)
                    p.drawLine(handles.front().second, point);
        }
        p.setPen(dark);
        for (const auto& [handle, point] : handles) {
            p.setBrush(handle == Handle::Centre ? QColor(255, 255, 255) : QColor(255, 200, 60));
            // A path's many points smaller, so the path between them stays seen.
            const double r = handle == Handle::PathPoint ? 3.0 : 5.0;
            p.drawEllipse(point, r, r);
        }
    }
}

} // namespace marbler::ui
