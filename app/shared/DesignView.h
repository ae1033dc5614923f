#pragma once
/// The canvas of the large view: one design drawn at the view's scale, zoomed and panned (a
/// flat design, each view re-rendered sharp through the render service) or zoomed and turned (a
/// solid on its object), or a flat design's repeat swatch. Until a view's render arrives, the
/// image shown last is drawn moved and scaled to the new view.

#include "marbler/Genome.h"
#include "marbler/Sampling.h"
#include "shared/ViewController.h"

#include <QImage>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <QWidget>

#include <cstdint>
#include <optional>

namespace marbler::ui {

class RenderService;

/// The part of the plane the repeat swatch of a design whose bath wraps shows: two tiles a side
/// from the origin, which the renderer fills with the design repeated on its own lattice.
Region swatchRegion(const Genome& genome);

class DesignView : public QWidget {
    Q_OBJECT
public:
    /// Shows `genome` (a solid on `mesh`; a flat design too when `flatOnObject`, laid on the
    /// object's texture coordinates and turned and zoomed as a solid is), rendered by `renderer`
    /// under a key of its own; `repeatSwatch`: starts with the swatch on (before the first
    /// render, so none is wasted).
    DesignView(const Genome& genome, RenderService* renderer, const QString& mesh, bool repeatSwatch,
               QWidget* parent = nullptr, bool flatOnObject = false);
    ~DesignView() override;

    /// Zoom and pan (flat designs; a solid's zoom magnifies its framed object).
    const ViewController& viewController() const { return mViewController; }
    /// The magnification of a solid's framed object (1: framed).
    double objectZoom() const { return mObjectZoom; }
    /// The angle a solid is seen from.
    ViewAngle viewAngle() const { return mAngle; }
    /// The zoom level shown, e.g. "250 %" (a flat design's scale, a solid's magnification).
    QString zoomText() const;
    /// The image shown now (coarse or final) and whether it is the final one for the view.
    const QImage& image() const { return mImage; }
    bool imageIsFinal() const { return mImageFinal; }
    /// The region the newest render was asked for (flat designs).
    std::optional<Region> requestedRegion() const { return mRequestRegion; }

    /// By a step of the + and - keys (a factor of √2), about the view's centre.
    void zoomIn();
    void zoomOut();
    /// Zooms by a factor keeping the point under `anchor` (widget coordinates) in place.
    void zoomAt(double factor, QPointF anchor);
    /// Shows the whole design; a solid's object framed.
    void fitView();
    /// One design unit to a screen pixel (flat designs).
    void showOneToOne();
    /// Moves a flat design by a drag of `delta` widget pixels.
    void panBy(QPointF delta);
    /// The repeat swatch (flat designs): the whole design and its mirror images 2 x 2, fitted to
    /// the canvas whatever the zoom; a design whose bath wraps repeated 2 x 2 on its own lattice
    /// (straight, half-drop or brick) instead, the render of swatchRegion. image() is then the
    /// tiled image.
    void setRepeatSwatch(bool on);
    bool repeatSwatch() const { return mSwatch; }
    /// A solid shown by this cross-section (the whole plane fitted to the canvas) instead of on
    /// its object; none: on its object again. Flat designs ignore it.
    void setSection(const std::optional<Slice>& slice);
    const std::optional<Slice>& section() const { return mSection; }

signals:
    /// The zoom or the part shown changed (zoomText() says the new zoom).
    void zoomChanged();
    /// The user turned the solid object (at the end of the drag).
    void viewAngleChanged(const marbler::ui::ViewAngle& angle);

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;

private:
    /// Where the image shown goes (widget coordinates): moved and scaled by any view change since
    /// it was rendered, so a change shows at once, coarse, until the new render arrives.
    QRectF imageTarget() const;
    void viewChanged(bool previewOnly = false);
    void requestRender(bool previewOnly = false);

    Genome mGenome;
    RenderService* mRenderer;
    QString mMesh;
    bool mFlatOnObject = false;
    bool mOnObject = false; ///< a solid, or a flat design on an object: seen on the object
    std::uint64_t mKey;
    ViewController mViewController; ///< in device pixels of the canvas
    double mObjectZoom = 1.0;
    ViewAngle mAngle;
    /// The image shown, and the view it was rendered for (a region or a solid's zoom).
    QImage mImage;
    bool mImageFinal = false;
    Region mImageRegion;
    double mImageZoom = 1.0;
    QString mMessage; ///< shown instead of an image ("rendering…", a failure)
    /// The view of the newest request: what its results show.
    std::optional<Region> mRequestRegion;
    double mRequestZoom = 1.0;
    QPointF mLastPos;
    bool mDragging = false;
    bool mSwatch = false;          ///< the repeat swatch is on
    std::optional<Slice> mSection; ///< a solid shown by this cross-section, not on its object
    bool mRequestSwatch = false;   ///< the newest request is for the swatch
    bool mImageSwatch = false;     ///< mImage is the swatch (tiled), centred on the canvas
};

} // namespace marbler::ui
