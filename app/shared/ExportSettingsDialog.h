#pragma once
/// Export image's settings: the format, size (in pixels or as a print size), antialiasing, the
/// mirror repeat tile of a flat design and the view of a solid one, checked against the
/// renderer's limits before any work starts.

#include "marbler/Genome.h"
#include "marbler/PrintProfile.h"
#include "marbler/Sampling.h"

#include <QDialog>
#include <QSize>
#include <QString>

#include <functional>
#include <optional>
#include <string>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;

namespace marbler::ui {

/// What the export of a solid design shows: its object as the large view shows it (mesh, angle,
/// zoom), or a cross-section at any axis and position.
struct SolidExport {
    bool objectView = false;
    Slice slice{2, 0.0}; ///< the cross-section, when not the object view
};

/// Why an image of this many pixels cannot be exported (empty when it can): the renderer's
/// limits MaxImageSide and MaxImagePixels (marbler/Sampling.h), said in pixels and megapixels.
QString exportSizeProblem(QSize pixels);

/// How Export image asks for a printer's ICC profile: the file chosen, or empty when none
/// (QFileDialog by default; tests replace it so no dialog blocks).
using ProfileChooser = std::function<QString(QWidget* parent, const QString& current)>;
void setProfileChooser(ProfileChooser chooser);

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
    /// Whether a raster is exported as its straight repeat tile, the render 2 x 2 (offered only
    /// for a design whose bath wraps; twice the size). It and the mirror repeat exclude each other.
    bool straightRepeatTile() const;
    void setStraightRepeatTile(bool on);
    /// The printer's ICC profile a TIFF is converted to (Convert to printer profile, flat designs;
    /// remembered as QSettings files/exportPrintProfile), when that is ticked and the format is
    /// a TIFF; nullopt otherwise.
    std::optional<QString> printProfile() const;
    /// Ticks Convert to printer profile with `file` (empty: unticks it).
    void setPrintProfile(const QString& file);
    RenderingIntent intent() const;
    /// Whether the format is Separations (a folder of masks and the indexed PNG; flat designs).
    bool separations() const;
    /// The separations' masks: 8 (coverage) or 1 (for screens).
    int maskBits() const;
    void setMaskBits(int bits);
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
    /// What to type when the size is too large: the widest image that fits the renderer's
    /// limits, in the unit shown (`tiles`: 2 for a repeat tile's 2 x 2).
    QString widestThatFits(int tiles) const;

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
    QLineEdit* mNormal = nullptr;        ///< solids: a turned cross-section's normal (empty: across the axis)
    /// The cross-section the solid's rows say (a normal typed that does not parse: across the axis).
    Slice chosenSlice() const;
    QLabel* mPixels = nullptr;
    QDoubleSpinBox* mTolerance = nullptr; ///< flat designs: the SVG's tolerance
    QCheckBox* mRepeat = nullptr;         ///< flat designs: the mirror repeat tile
    QCheckBox* mStraight = nullptr;       ///< designs whose bath wraps: the straight repeat tile
    QCheckBox* mCmyk = nullptr;           ///< flat designs: convert the TIFF to a printer profile
    QLineEdit* mProfile = nullptr;        ///< the printer profile's file
    QPushButton* mChooseProfile = nullptr;
    QComboBox* mIntent = nullptr;   ///< the conversion's rendering intent
    QComboBox* mMaskBits = nullptr; ///< separations: 8-bit coverage or 1-bit masks
    QDialogButtonBox* mButtons = nullptr;
};

} // namespace marbler::ui
