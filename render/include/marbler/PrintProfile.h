#pragma once
/// A CMYK TIFF for a printer's ICC profile (issue 29): the sRGB render converted by LittleCMS
/// (Debian's liblcms2) to the colour space of a CMYK output profile, with that profile
/// embedded, for a print shop that asks for files in its own press's colours. `marbler render
/// --icc PRINTER.icc` and the window's export write it.

#include "marbler/CpuRenderer.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace marbler {

/// How colours outside the printer's gamut are mapped (the ICC rendering intents).
enum class RenderingIntent { Perceptual, RelativeColorimetric, Saturation, AbsoluteColorimetric };

/// The intents as the command line names them: "perceptual", "relative", "saturation",
/// "absolute", in the enum's order.
std::vector<std::string> renderingIntentNames();
/// The intent a name says; nullopt for any other word.
std::optional<RenderingIntent> parseRenderingIntent(std::string_view name);

/// A printer's profile, read and checked.
struct PrintProfile {
    std::vector<unsigned char> bytes; ///< the file as it is, embedded unchanged
    std::string description;          ///< the profile's own name for itself (may be empty)
};

/// Reads an ICC profile and checks it is a CMYK output (printer) profile LittleCMS can use.
/// Throws InputError naming the file: unreadable, not an ICC profile, a profile of another
/// class (a display's, a camera's, ...) or of another colour space (RGB, grey, ...).
PrintProfile loadPrintProfile(const std::filesystem::path& file);

/// Converts 8-bit or 16-bit sRGB pixels (3 values a pixel) to the profile's CMYK (4 values a
/// pixel, 0 no ink), as LittleCMS transforms from its built-in sRGB profile with `intent`.
class CmykConversion {
public:
    /// Throws InputError when LittleCMS cannot build the transform from the profile;
    /// bitsPerSample 8 or 16.
    CmykConversion(const PrintProfile& profile, RenderingIntent intent, int bitsPerSample);
    ~CmykConversion();
    CmykConversion(const CmykConversion&) = delete;
    CmykConversion& operator=(const CmykConversion&) = delete;

    /// `pixels` pixels of uint8_t (8 bits) or uint16_t (16 bits) values.
    void convert(const void* rgb, void* cmyk, std::size_t pixels) const;

private:
    void* mTransform = nullptr;
};

/// How a CMYK TIFF is written.
struct CmykTiffOptions {
    RenderingIntent intent = RenderingIntent::Perceptual;
    int bitsPerSample = 8;     ///< 8 or 16 (16: from the linear average, as the 16-bit RGB TIFF)
    std::optional<double> dpi; ///< written into the file's resolution when set
    std::string genome;        ///< carried in the XMP packet as every TIFF does; empty: the render's
};

/// Renders `genome` in strips and writes `file` (.tif or .tiff) as a CMYK TIFF: 4 samples a
/// pixel, PHOTOMETRIC_SEPARATED, the profile embedded, atomically (nothing is left on failure
/// or cancel). Throws InputError for another extension, a bad depth or bad settings,
/// RuntimeFailure for I/O failures, Cancelled.
void renderToCmykTiff(const Genome& genome, const RenderSettings& settings, const std::filesystem::path& file,
                      const PrintProfile& profile, const CmykTiffOptions& options = {},
                      const RenderControl* control = nullptr);

} // namespace marbler
