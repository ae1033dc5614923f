#pragma once
/// One design shown large: zoom and pan a flat design (each view re-rendered sharp at its
/// scale), zoom and turn a solid one, save its genome, export an image at a chosen size, and
/// open it in the editor.

#include "marbler/Genome.h"
#include "marbler/Sampling.h"
#include "shared/ExportSettingsDialog.h"
#include "shared/ViewController.h"

#include <QDialog>
#include <QImage>

#include <optional>
#include <string>

class QLabel;
class QToolButton;

namespace marbler::ui {

class DesignExport;
class DesignView;
class RenameDialog;
class RenderService;
class SectionControls;

class DesignDialog : public QDialog {
    Q_OBJECT
public:
    /// Shows `genome` large: a solid on `mesh`, a flat design flat, or on `flatMesh` (laid on its
    /// texture coordinates) where that is not empty.
    DesignDialog(Genome genome, RenderService* renderer, const QString& mesh, QWidget* parent = nullptr,
                 const QString& flatMesh = QString());
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
    /// mirror` does (marbler/Repeat.h); `straightRepeatTile` the render 2 x 2, for a design whose
    /// bath wraps.
    bool exportTo(const QString& file, QSize pixels, const QString& aa = QStringLiteral("rgss"),
                  std::optional<double> dpi = std::nullopt, std::optional<SolidExport> solid = std::nullopt,
                  int bitsPerSample = 8, bool mirrorRepeatTile = false, bool straightRepeatTile = false);
    /// Starts writing the design as SVG, as `marbler svg --tolerance` does (traceDesign and
    /// writeSvg: one layer per ink, knocked out, in mm; written atomically), on the export thread with the
    /// same progress box and exportFinished. A solid or a design with a source image fails with the library's
    /// reason. Returns false when an export is already running.
    bool exportSvgTo(const QString& file, double tolerance = 1.0);
    /// Starts rendering the design (flat) as a CMYK TIFF converted to the printer's ICC profile
    /// `profile` (as marbler render --icc; issue 29), on the export thread with the same
    /// progress box and exportFinished. A profile that is no CMYK printer profile fails with
    /// the library's reason. Returns false when an export is already running or the size is
    /// beyond the renderer's limits.
    bool exportCmykTo(const QString& file, QSize pixels, const QString& aa, std::optional<double> dpi,
                      const QString& profile, RenderingIntent intent = RenderingIntent::Perceptual,
                      int bitsPerSample = 8);
    /// Starts writing the design's separations into `folder` (as marbler render --separations: a
    /// mask per ink, 8-bit coverage or 1-bit, and indexed.png), with the same progress box,
    /// cancel and exportFinished (its file: the folder). Returns false as exportTo does.
    bool exportSeparationsTo(const QString& folder, QSize pixels, const QString& aa = QStringLiteral("rgss"),
                             std::optional<double> dpi = std::nullopt, int maskBits = 8);
    /// Puts the genome on the clipboard as genome text (the Copy genome button, Ctrl+C).
    void copyGenome();
    /// Stops a running export; no file is left behind.
    void cancelExport();
    bool isExporting() const;
    /// The file Export offers: the design's name made safe, with the format and in the folder
    /// used last (QSettings files/exportExtension and files/exportDir; PNG at first).
    QString suggestedExportFile() const;

    /// Zoom and pan (flat designs; a solid's zoom magnifies its framed object).
    const ViewController& viewController() const;
    /// The magnification of a solid's framed object (1: framed).
    double objectZoom() const;
    /// The angle a solid is seen from (the design's meta.view).
    ViewAngle viewAngle() const;
    /// The zoom level shown, e.g. "250 %" (a flat design's scale, a solid's magnification).
    QString zoomText() const;
    /// The image shown now (coarse or final) and whether it is the final one for the view.
    const QImage& image() const;
    bool imageIsFinal() const;
    /// The region the newest render was asked for (flat designs).
    std::optional<Region> requestedRegion() const;
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
    bool repeatSwatch() const;
    /// A solid shown by this cross-section (across an axis, or turned to any normal) instead of
    /// on its object; none: on its object (the Section button, S). Export image starts with the
    /// section shown. Flat designs ignore it.
    void setSection(const std::optional<Slice>& slice);
    const std::optional<Slice>& section() const;
    /// F2: asks for the design's name and note (not modal); returns the dialog.
    RenameDialog* askName();
    /// Names the design shown (meta.name, meta.note) and says so in the title; no signal.
    void rename(const QString& name, const QString& note);

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
    /// The user named the design (F2, or Save genome under a name of their own); genome() has the
    /// name and note. The window may give another name (unique in its session) with rename().
    void renamed(const marbler::Genome& design);

protected:
    void keyPressEvent(QKeyEvent* event) override;

private:
    void exportImage();

    Genome mGenome;
    RenderService* mRenderer;
    QString mMesh;
    DesignView* mView = nullptr;     ///< the canvas: the design zoomed, panned or turned
    DesignExport* mExport = nullptr; ///< the export pipeline
    QLabel* mZoomLabel = nullptr;
    QToolButton* mSwatchButton = nullptr;
    QToolButton* mSectionButton = nullptr;       ///< a solid: show a cross-section (S)
    SectionControls* mSectionControls = nullptr; ///< where the section lies and how it is turned
    Slice mLastSection{2, 0.0};                  ///< the section shown last (shown again on S)
};

/// Asks for a file name (offering the design's name made safe, in the folder used last) and saves
/// the genome atomically; errors are reported. Returns the file written, empty when cancelled or
/// failed.
/// When the user typed a file name of their own, the design saved takes it as its name
/// (adoptFileName, RenameDialog.h); `saved`, when given, receives the design as written.
QString saveGenomeWithDialog(QWidget* parent, const Genome& genome, Genome* saved = nullptr);
/// Saves the genome atomically to a file; errors are reported. Returns success.
bool saveGenomeTo(QWidget* parent, const Genome& genome, const QString& file);

} // namespace marbler::ui
