#pragma once
/// One design shown large: zoom and pan a flat design (each view re-rendered sharp at its
/// scale), zoom and turn a solid one, save its genome, export an image at a chosen size, and
/// open it in the editor.

#include "marbler/Genome.h"
#include "marbler/Sampling.h"
#include "ui/ViewController.h"

#include <QDialog>
#include <QImage>
#include <QPointer>

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QSpinBox;
class QThread;
class QToolButton;

namespace marbler {
struct RenderControl;
}

namespace marbler::ui {

/// What the export of a solid design shows: its object as the large view shows it (mesh, angle,
/// zoom), or a cross-section at any axis and position.
struct SolidExport {
    bool objectView = false;
    Slice slice{2, 0.0}; ///< the cross-section, when not the object view
};

class BackgroundJob;
class DesignCanvas;
class RenderService;

class DesignDialog : public QDialog {
    Q_OBJECT
public:
    DesignDialog(Genome genome, RenderService* renderer, const QString& mesh, QWidget* parent = nullptr);
    ~DesignDialog() override;

    const Genome& genome() const { return mGenome; }
    /// Saves the genome to a file (atomically: a temporary renamed over it); errors are
    /// reported. Returns success.
    bool saveTo(const QString& file);
    /// Starts rendering the design to an image file (format by extension) at a pixel size on a
    /// thread of its own, written atomically; exportFinished follows. Returns false when an
    /// export is already running, or when the size is beyond the renderer's limits (reported,
    /// see exportSizeProblem). `bitsPerSample` 16 makes a 16-bit TIFF. A solid shows `solid`
    /// (its middle z cross-section when unset). `mirrorRepeatTile` (flat designs) writes the
    /// mirror repeat of the render instead, twice `pixels` each way, as `marbler render --repeat
    /// mirror` does (marbler/Repeat.h).
    bool exportTo(const QString& file, QSize pixels, const QString& aa = QStringLiteral("rgss"),
                  std::optional<double> dpi = std::nullopt, std::optional<SolidExport> solid = std::nullopt,
                  int bitsPerSample = 8, bool mirrorRepeatTile = false);
    /// Starts writing the design as SVG, as `marbler svg --tolerance` does (traceDesign and
    /// toSvg, written atomically), on the export thread with the same progress box and
    /// exportFinished. A solid or a design with a source image fails with the library's reason.
    /// Returns false when an export is already running.
    bool exportSvgTo(const QString& file, double tolerance = 1.0);
    /// Puts the genome on the clipboard as genome text (the Copy genome button, Ctrl+C).
    void copyGenome();
    /// Stops a running export; no file is left behind.
    void cancelExport();
    bool isExporting() const { return !mExport.isNull(); }
    /// The file Export offers: the design's name made safe, with the format and in the folder
    /// used last (QSettings files/exportExtension and files/exportDir; PNG at first).
    QString suggestedExportFile() const;

    /// Zoom and pan (flat designs; a solid's zoom magnifies its framed object).
    const ViewController& viewController() const { return mViewController; }
    /// The magnification of a solid's framed object (1: framed).
    double objectZoom() const { return mObjectZoom; }
    /// The angle a solid is seen from (the design's meta.view).
    ViewAngle viewAngle() const { return mAngle; }
    /// The zoom level shown, e.g. "250 %" (a flat design's scale, a solid's magnification).
    QString zoomText() const;
    /// The image shown now (coarse or final) and whether it is the final one for the view.
    const QImage& image() const { return mImage; }
    bool imageIsFinal() const { return mImageFinal; }
    /// The region the newest render was asked for (flat designs).
    std::optional<Region> requestedRegion() const { return mRequestRegion; }
    /// The widget the design is drawn in (it takes the wheel and drags).
    QWidget* canvas() const;

    /// By a step of the + and - keys (a factor of √2), about the view's centre.
    void zoomIn();
    void zoomOut();
    /// Zooms by a factor keeping the point under `anchor` (canvas coordinates) in place.
    void zoomAt(double factor, QPointF anchor);
    /// Shows the whole design (the 0 key); a solid's object framed.
    void fitView();
    /// One design unit to a screen pixel (the 1 key; flat designs).
    void showOneToOne();
    /// Moves a flat design by a drag of `delta` canvas pixels.
    void panBy(QPointF delta);
    /// The repeat swatch (flat designs; the R key, remembered as QSettings view/repeatSwatch):
    /// the whole design and its mirror images 2 x 2, as the mirror repeat tile prints, fitted
    /// to the canvas whatever the zoom, to judge the repeat. image() is then the tiled image.
    void setRepeatSwatch(bool on);
    bool repeatSwatch() const { return mSwatch; }

signals:
    /// The user turned the solid object; the angle is already in genome()'s meta.view.
    void viewAngleChanged(const marbler::ui::ViewAngle& angle);
    /// A file the user asked for was written: the genome saved or an image exported (the
    /// window's status bar says where, with "Show in folder").
    void fileSaved(const QString& file);
    /// The genome was put on the clipboard; `name` is the design's (the window says so).
    void genomeCopied(const QString& name);
    /// An export ended: written (the file is complete), or cancelled or failed (`error` says
    /// why for a failure; nothing is left behind either way).
    void exportFinished(const QString& file, bool written, const QString& error);
    /// "Open in editor": the workbench opens the design in an editor window.
    void openInEditorRequested(const marbler::Genome& design);

protected:
    void keyPressEvent(QKeyEvent* event) override;

private:
    friend class DesignCanvas;
    void canvasResized();
    void canvasPressed(QMouseEvent* event);
    void canvasMoved(QMouseEvent* event);
    void canvasReleased(QMouseEvent* event);
    /// Where the image shown goes on the canvas (canvas coordinates): moved and scaled by any
    /// view change since it was rendered, so a change shows at once, coarse, until the new
    /// render arrives.
    QRectF imageTarget() const;
    void viewChanged(bool previewOnly = false);
    void requestRender(bool previewOnly = false);
    void exportImage();
    /// Runs `job` on the export thread with the progress box and its Cancel; exportFinished and
    /// fileSaved follow. `busy`: the job reports no progress (the box shows activity instead).
    bool startExport(const QString& file, std::function<void(const RenderControl&)> job, bool busy = false);

    Genome mGenome;
    RenderService* mRenderer;
    QString mMesh;
    std::uint64_t mKey;
    DesignCanvas* mCanvas = nullptr;
    QLabel* mZoomLabel = nullptr;
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
    bool mSwatch = false;        ///< the repeat swatch is on
    bool mRequestSwatch = false; ///< the newest request is for the swatch
    bool mImageSwatch = false;   ///< mImage is the swatch (tiled), centred on the canvas
    QToolButton* mSwatchButton = nullptr;
    QPointer<BackgroundJob> mExport; ///< the export running, if any
};

/// Why an image of this many pixels cannot be exported (empty when it can): the renderer's
/// limits MaxImageSide and MaxImagePixels (marbler/Sampling.h), said in pixels and megapixels.
QString exportSizeProblem(QSize pixels);

/// The format, size and antialiasing of an exported image, in pixels or as a print size (cm, mm,
/// inches) at a dpi; for a solid design, whether it shows the object or a cross-section. Changing the unit
/// converts the width at the dpi, so the image keeps its pixels; changing the dpi of a print size keeps the
/// print size. Sizes beyond the renderer's limits are refused with the reason, before any work starts.
class ExportSettingsDialog : public QDialog {
    Q_OBJECT
public:
    explicit ExportSettingsDialog(const Genome& genome, QWidget* parent = nullptr);

    /// The unit by its label: "pixels", "cm", "mm" or "inches".
    void setUnit(const QString& unit);
    QString unit() const;
    /// The width in the current unit.
    double widthValue() const;
    void setWidthValue(double value);
    void setDpi(int dpi);
    /// The image size in pixels (the height keeps the design's proportions).
    QSize pixels() const;
    std::optional<double> dpi() const;
    std::string aa() const;
    /// The format: its extension (".png", ".jpg", ".tif", ".exr") and a TIFF's bits a sample.
    QString extension() const;
    int bitsPerSample() const;
    /// Chooses a format by extension and depth (".tif", 16: the 16-bit TIFF).
    void setFormat(const QString& extension, int bitsPerSample = 8);
    /// The SVG's tolerance in design units (the format ".svg"; `marbler svg --tolerance`).
    double tolerance() const;
    /// Whether a raster is exported as its mirror repeat tile (flat designs; twice the size).
    bool mirrorRepeatTile() const;
    void setMirrorRepeatTile(bool on);
    /// A solid design's view (unset for a flat design).
    std::optional<SolidExport> solidExport() const;
    void setSolidExport(const SolidExport& solid);

    void accept() override;

private:
    double perInch() const;
    /// The image's height over its width: the design's, a cross-section's plane's, or 1 for
    /// the object view (framed whatever the proportions; square like the grid's cells).
    double aspect() const;
    void showWidth();
    void updateSummary();
    bool isSvg() const;

    Genome mGenome;
    double mPixelWidth = 2048.0; ///< the chosen width in pixels, exact whatever unit shows it
    bool mShowing = false;       ///< the width field is being set from mPixelWidth
    QComboBox* mUnit = nullptr;
    QDoubleSpinBox* mWidth = nullptr;
    QSpinBox* mDpi = nullptr;
    QComboBox* mAa = nullptr;
    QComboBox* mFormat = nullptr;
    QComboBox* mSolidView = nullptr;     ///< solids: object view or cross-section
    QComboBox* mAxis = nullptr;          ///< solids: the cross-section's axis
    QDoubleSpinBox* mPosition = nullptr; ///< solids: the cross-section's position on its axis
    QLabel* mPixels = nullptr;
    QDoubleSpinBox* mTolerance = nullptr; ///< flat designs: the SVG's tolerance
    QCheckBox* mRepeat = nullptr;         ///< flat designs: the mirror repeat tile
    QDialogButtonBox* mButtons = nullptr;
};

/// Asks for a file name (offering the design's name made safe, in the folder used last) and saves
/// the genome atomically; errors are reported. Returns the file written, empty when cancelled or
/// failed.
QString saveGenomeWithDialog(QWidget* parent, const Genome& genome);
/// Saves the genome atomically to a file; errors are reported. Returns success.
bool saveGenomeTo(QWidget* parent, const Genome& genome, const QString& file);

} // namespace marbler::ui
