#include "shared/ViewController.h"

#include <QKeyEvent>

#include <algorithm>
#include <cmath>

namespace marbler::ui {

ViewAngle ViewAngle::dragged(double dx, double dy) const {
    return {std::fmod(yaw + dx * 0.5, 360.0), std::clamp(pitch + dy * 0.5, -89.0, 89.0)};
}

ViewAngle viewAngleOf(const Genome& genome) {
    ViewAngle angle;
    if (!genome.meta.view) return angle;
    angle.yaw = genome.meta.view->yaw.value_or(angle.yaw);
    angle.pitch = genome.meta.view->pitch.value_or(angle.pitch);
    angle.pitch = std::clamp(angle.pitch, -89.0, 89.0);
    return angle;
}

void setViewAngle(Genome& genome, const ViewAngle& angle) {
    genome.meta.view = MetaView{angle.yaw, angle.pitch, {}};
}

void ViewController::setDesignSize(double width, double height) {
    mWidth = width > 0.0 ? width : 1.0;
    mHeight = height > 0.0 ? height : 1.0;
    if (mFitted) fit();
    clampCentre();
}

void ViewController::setViewport(QSize pixels) {
    mViewport = pixels.expandedTo(QSize(1, 1));
    if (mFitted) fit();
}

double ViewController::fitScale() const {
    return std::min(mViewport.width() / mWidth, mViewport.height() / mHeight);
}

void ViewController::fit() {
    mScale = fitScale();
    mCentre = QPointF(mWidth / 2.0, mHeight / 2.0);
    mFitted = true;
}

void ViewController::oneToOne() {
    setScale(1.0, QPointF(mViewport.width() / 2.0, mViewport.height() / 2.0));
}

void ViewController::zoomBy(double factor, QPointF anchor) {
    setScale(mScale * factor, anchor);
}

void ViewController::setScale(double scale, QPointF anchor) {
    const QPointF fixed = toDesign(anchor);
    mScale = std::clamp(scale, std::min(MinFitFraction * fitScale(), MaxScale), MaxScale);
    // The point under the anchor stays there: solve toViewport(fixed) == anchor for the centre.
    const QPointF half(mViewport.width() / 2.0, mViewport.height() / 2.0);
    mCentre = fixed - (anchor - half) / mScale;
    mFitted = false;
    clampCentre();
}

void ViewController::panBy(QPointF delta) {
    mCentre -= delta / mScale;
    mFitted = false;
    clampCentre();
}

void ViewController::clampCentre() {
    // The design can be moved aside but never lost: the view's centre stays on it.
    mCentre.setX(std::clamp(mCentre.x(), 0.0, mWidth));
    mCentre.setY(std::clamp(mCentre.y(), 0.0, mHeight));
}

QPointF ViewController::toViewport(QPointF design) const {
    return (design - mCentre) * mScale + QPointF(mViewport.width() / 2.0, mViewport.height() / 2.0);
}

QPointF ViewController::toDesign(QPointF viewport) const {
    return (viewport - QPointF(mViewport.width() / 2.0, mViewport.height() / 2.0)) / mScale + mCentre;
}

QRectF ViewController::toViewport(const Region& region) const {
    return QRectF(toViewport(QPointF(region.x0, region.y0)), toViewport(QPointF(region.x1, region.y1)));
}

std::optional<ViewController::Window> ViewController::visibleWindow() const {
    const QRectF design = toViewport(Region{0.0, 0.0, mWidth, mHeight});
    const int x0 = std::max(0, int(std::floor(design.left())));
    const int y0 = std::max(0, int(std::floor(design.top())));
    const int x1 = std::min(mViewport.width(), int(std::ceil(design.right())));
    const int y1 = std::min(mViewport.height(), int(std::ceil(design.bottom())));
    if (x1 <= x0 || y1 <= y0) return std::nullopt;
    const QPointF a = toDesign(QPointF(x0, y0)), b = toDesign(QPointF(x1, y1));
    return Window{QRect(QPoint(x0, y0), QPoint(x1 - 1, y1 - 1)), Region{a.x(), a.y(), b.x(), b.y()}};
}

bool ViewController::handleKey(const QKeyEvent* event, const ZoomKeyActions& actions) {
    const std::function<void()>* action = nullptr;
    switch (event->key()) {
    case Qt::Key_Plus:
    case Qt::Key_Equal:
        action = &actions.zoomIn;
        break;
    case Qt::Key_Minus:
        action = &actions.zoomOut;
        break;
    case Qt::Key_0:
        action = &actions.fit;
        break;
    case Qt::Key_1:
        action = &actions.oneToOne;
        break;
    default:
        return false;
    }
    if (!*action) return false;
    (*action)();
    return true;
}

} // namespace marbler::ui
