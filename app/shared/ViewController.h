#pragma once
/// The view of one design: where a flat design is looked at (a centre and a scale, zoomed and
/// panned) and how a solid one is seen (its angle, kept in the design, and a magnification).
/// No widgets here: the large view drives it and draws what it says, and tests check its
/// arithmetic alone.

#include "marbler/Genome.h"
#include "marbler/Sampling.h"

#include <QPointF>
#include <QRect>
#include <QRectF>
#include <QSize>

#include <functional>
#include <optional>

class QKeyEvent;

namespace marbler::ui {

/// The angle a solid design is seen from, in degrees. It belongs to the design, not to the cell
/// showing it: kept in `meta.view` ({"yaw": 30, "pitch": 20}), it follows the design into other
/// cells, genome files and the session.
struct ViewAngle {
    double yaw = 30.0;
    double pitch = 20.0;
    friend bool operator==(const ViewAngle&, const ViewAngle&) = default;
    /// Turned by a mouse drag of `dx`, `dy` pixels (half a degree a pixel; the pitch stops short
    /// of the poles).
    ViewAngle dragged(double dx, double dy) const;
};
/// `meta.view` (missing or non-numeric entries read as the default 30, 20).
ViewAngle viewAngleOf(const Genome& genome);
/// Writes `meta.view`.
void setViewAngle(Genome& genome, const ViewAngle& angle);

/// Zoom and pan over a flat design, in the device pixels of a viewport. The scale is device
/// pixels per design unit: 1 is "1:1", one design unit to a screen pixel, the scale at which
/// `marbler render --width W` draws a design W units wide (100 %). Until the user zooms or pans,
/// the view is fitted: it follows the viewport, showing the whole design centred.
class ViewController {
public:
    /// Scales below a fraction of the fitted one are of no use. MaxScale (100 000 %) puts a
    /// thousandth of a design unit in a pixel, far below anything a tool draws, and still far
    /// above the precision of the doubles the maps run in.
    static constexpr double MinFitFraction = 0.25;
    static constexpr double MaxScale = 1000.0;

    /// The design space shown (its width and height in design units).
    void setDesignSize(double width, double height);
    /// The viewport in device pixels; a fitted view fits again.
    void setViewport(QSize pixels);
    QSize viewport() const { return mViewport; }

    double scale() const { return mScale; }
    /// The design point at the viewport's centre.
    QPointF centre() const { return mCentre; }
    bool isFitted() const { return mFitted; }
    /// The scale that shows the whole design.
    double fitScale() const;

    /// Shows the whole design, centred, and follows the viewport again.
    void fit();
    /// One design unit to a device pixel, about the viewport's centre.
    void oneToOne();
    /// Zooms by a factor keeping the design point under `anchor` (viewport pixels) in place;
    /// the scale stays within [MinFitFraction * fitScale, MaxScale].
    void zoomBy(double factor, QPointF anchor);
    void setScale(double scale, QPointF anchor);
    /// Moves the design by a drag of `delta` viewport pixels; the centre stays on the design.
    void panBy(QPointF delta);

    QPointF toViewport(QPointF design) const;
    QPointF toDesign(QPointF viewport) const;
    QRectF toViewport(const Region& region) const;

    /// The part of the design the viewport shows, snapped out to whole viewport pixels: the
    /// pixels it covers and the design rectangle they show exactly (so a render of `pixels`'
    /// size over `region` lands pixel for pixel). Empty when no part of the design is in view.
    struct Window {
        QRect pixels;
        Region region;
    };
    std::optional<Window> visibleWindow() const;

    /// What a view does for each zoom key (its own step, about its centre; a solid's view
    /// magnifies its object). An empty action leaves its key to the widget.
    struct ZoomKeyActions {
        std::function<void()> zoomIn, zoomOut, fit, oneToOne;
    };
    /// The zoom keys of every view (the large view, the editor's canvas): + or = zooms in, -
    /// out, 0 fits, 1 shows one to one, with or without Ctrl or the keypad (Ctrl++ is the
    /// platform's zoom). Runs the key's action and returns true, or returns false for any other
    /// key (the widget's own).
    static bool handleKey(const QKeyEvent* event, const ZoomKeyActions& actions);

private:
    void clampCentre();

    double mWidth = 1.0, mHeight = 1.0;
    QSize mViewport{1, 1};
    QPointF mCentre{0.5, 0.5};
    double mScale = 1.0;
    bool mFitted = true;
};

} // namespace marbler::ui
