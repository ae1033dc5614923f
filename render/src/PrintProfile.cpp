#include "marbler/PrintProfile.h"

#include "marbler/AtomicFile.h"
#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/GenomeImage.h"
#include "marbler/Image.h"
#include "marbler/ImageFormats.h"

#include <lcms2.h>
#include <tiffio.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <utility>

namespace marbler {
namespace fs = std::filesystem;
namespace {

cmsUInt32Number lcmsIntent(RenderingIntent intent) {
    switch (intent) {
    case RenderingIntent::Perceptual:
        return INTENT_PERCEPTUAL;
    case RenderingIntent::RelativeColorimetric:
        return INTENT_RELATIVE_COLORIMETRIC;
    case RenderingIntent::Saturation:
        return INTENT_SATURATION;
    case RenderingIntent::AbsoluteColorimetric:
        return INTENT_ABSOLUTE_COLORIMETRIC;
    }
    return INTENT_PERCEPTUAL;
}

/// A profile class in words, for the message that refuses it.
std::string className(cmsProfileClassSignature c) {
    switch (c) {
    case cmsSigInputClass:
        return "an input (scanner or camera) profile";
    case cmsSigDisplayClass:
        return "a display profile";
    case cmsSigOutputClass:
        return "an output profile";
    case cmsSigLinkClass:
        return "a device link";
    case cmsSigAbstractClass:
        return "an abstract profile";
    case cmsSigColorSpaceClass:
        return "a colour space profile";
    case cmsSigNamedColorClass:
        return "a named colour profile";
    }
    return "a profile of an unknown class";
}

std::string spaceName(cmsColorSpaceSignature s) {
    switch (s) {
    case cmsSigRgbData:
        return "RGB";
    case cmsSigGrayData:
        return "grey";
    case cmsSigCmyData:
        return "CMY";
    case cmsSigLabData:
        return "Lab";
    case cmsSigXYZData:
        return "XYZ";
    default:
        break;
    }
    // Any other space by its four-letter signature.
    std::string name;
    for (int shift = 24; shift >= 0; shift -= 8)
        name += char((std::uint32_t(s) >> shift) & 0xff);
    while (!name.empty() && name.back() == ' ')
        name.pop_back();
    return name + (name.size() > 1 && std::isdigit(static_cast<unsigned char>(name[0])) ? " channels" : "");
}

struct ProfileHandle {
    cmsHPROFILE handle = nullptr;
    ~ProfileHandle() {
        if (handle) cmsCloseProfile(handle);
    }
};

/// libtiff's message for this file (TIFFOpenExt's own handler, so no process-wide one changes).
int tiffErrorHandler(TIFF*, void* user, const char* module, const char* format, va_list args) {
    char text[512];
    std::vsnprintf(text, sizeof text, format, args);
    *static_cast<std::string*>(user) = module && *module ? std::string(module) + ": " + text : text;
    return 1;
}

[[noreturn]] void failWrite(const fs::path& file, const std::string& reason, int error) {
    if (error == ENOSPC || error == EDQUOT) throw RuntimeFailure(writeFailureMessage(file, error));
    throw RuntimeFailure(writeFailureMessage(file, error, reason));
}

} // namespace

std::vector<std::string> renderingIntentNames() {
    return {"perceptual", "relative", "saturation", "absolute"};
}

std::optional<RenderingIntent> parseRenderingIntent(std::string_view name) {
    const std::vector<std::string> names = renderingIntentNames();
    for (std::size_t i = 0; i < names.size(); ++i)
        if (name == names[i]) return static_cast<RenderingIntent>(i);
    return std::nullopt;
}

PrintProfile loadPrintProfile(const fs::path& file) {
    const std::string name = "'" + file.string() + "'";
    std::ifstream in(file, std::ios::binary);
    std::error_code ec;
    if (!in || fs::is_directory(file, ec))
        throw InputError(name + ": cannot read the printer profile (" +
                         (fs::exists(file, ec) ? "not a readable file" : "no such file") + ")");
    PrintProfile profile;
    profile.bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    // An ICC profile says so in its header: its size, then "acsp" at byte 36.
    if (profile.bytes.size() < 132 || std::memcmp(profile.bytes.data() + 36, "acsp", 4) != 0)
        throw InputError(
            name + ": not an ICC profile (an .icc or .icm file has the signature 'acsp' in its header)");
    ProfileHandle h{cmsOpenProfileFromMem(profile.bytes.data(), cmsUInt32Number(profile.bytes.size()))};
    if (!h.handle) throw InputError(name + ": a damaged ICC profile that LittleCMS cannot read");
    const cmsProfileClassSignature cls = cmsGetDeviceClass(h.handle);
    const cmsColorSpaceSignature space = cmsGetColorSpace(h.handle);
    if (cls != cmsSigOutputClass)
        throw InputError(name + ": " + className(cls) + ", not a printer's; give the CMYK output profile " +
                         "of the press or paper (a .icc file from the print shop)");
    if (space != cmsSigCmykData)
        throw InputError(name + ": a printer profile for " + spaceName(space) +
                         ", not CMYK; a CMYK TIFF needs a CMYK output profile");
    char text[256] = {};
    if (cmsGetProfileInfoASCII(h.handle, cmsInfoDescription, "en", "US", text, sizeof text) > 0)
        profile.description = text;
    return profile;
}

CmykConversion::CmykConversion(const PrintProfile& profile, RenderingIntent intent, int bitsPerSample) {
    if (bitsPerSample != 8 && bitsPerSample != 16)
        throw InputError("a CMYK TIFF holds 8 or 16 bits a sample (got " + std::to_string(bitsPerSample) +
                         ")");
    ProfileHandle srgb{cmsCreate_sRGBProfile()};
    ProfileHandle printer{cmsOpenProfileFromMem(profile.bytes.data(), cmsUInt32Number(profile.bytes.size()))};
    if (!srgb.handle || !printer.handle) throw InputError("LittleCMS cannot read the printer profile");
    const bool deep = bitsPerSample == 16;
    mTransform = cmsCreateTransform(srgb.handle, deep ? TYPE_RGB_16 : TYPE_RGB_8, printer.handle,
                                    deep ? TYPE_CMYK_16 : TYPE_CMYK_8, lcmsIntent(intent), 0);
    if (!mTransform)
        throw InputError("LittleCMS cannot convert sRGB to the printer profile" +
                         (profile.description.empty() ? std::string() : " '" + profile.description + "'") +
                         " with the " + renderingIntentNames()[std::size_t(intent)] + " intent");
}

CmykConversion::~CmykConversion() {
    if (mTransform) cmsDeleteTransform(static_cast<cmsHTRANSFORM>(mTransform));
}

void CmykConversion::convert(const void* rgb, void* cmyk, std::size_t pixels) const {
    // lcms2 takes a 32-bit count: long strips go in pieces.
    const std::size_t chunk = 1u << 20;
    const auto* in = static_cast<const unsigned char*>(rgb);
    auto* out = static_cast<unsigned char*>(cmyk);
    const cmsUInt32Number format = cmsGetTransformInputFormat(static_cast<cmsHTRANSFORM>(mTransform));
    const std::size_t bytes = T_BYTES(format);
    for (std::size_t p = 0; p < pixels; p += chunk) {
        const std::size_t n = std::min(chunk, pixels - p);
        cmsDoTransform(static_cast<cmsHTRANSFORM>(mTransform), in + p * 3 * bytes, out + p * 4 * bytes,
                       cmsUInt32Number(n));
    }
}

void renderToCmykTiff(const Genome& genome, const RenderSettings& settings, const fs::path& file,
                      const PrintProfile& profile, const CmykTiffOptions& options,
                      const RenderControl* control) {
    const std::string ext = lowerExtension(file);
    if (ext != ".tif" && ext != ".tiff")
        throw InputError("'" + file.string() +
                         "': a CMYK file for a printer profile is a TIFF (.tif or .tiff), not " +
                         (ext.empty() ? std::string("a file without an extension") : ext));
    checkRenderSettings(genome, settings);
    if (options.dpi && !(*options.dpi > 0.0 && std::isfinite(*options.dpi)))
        throw InputError("dpi must be a positive number");
    const CmykConversion conversion(profile, options.intent, options.bitsPerSample);
    const bool deep = options.bitsPerSample == 16;
    const int width = settings.width, height = settings.height;

    AtomicFile atomic(file);
    std::string message;
    TIFFOpenOptions* openOptions = TIFFOpenOptionsAlloc();
    TIFFOpenOptionsSetErrorHandlerExtR(openOptions, tiffErrorHandler, &message);
    TIFF* tiff = TIFFOpenExt(atomic.temporary().c_str(), "w", openOptions);
    TIFFOpenOptionsFree(openOptions);
    if (!tiff) failWrite(file, message.empty() ? std::strerror(errno) : message, errno);
    struct Closer {
        TIFF*& tiff;
        ~Closer() {
            if (tiff) TIFFClose(tiff);
        }
    } closer{tiff};

    constexpr int RowsPerStrip = 64;
    TIFFSetField(tiff, TIFFTAG_IMAGEWIDTH, std::uint32_t(width));
    TIFFSetField(tiff, TIFFTAG_IMAGELENGTH, std::uint32_t(height));
    TIFFSetField(tiff, TIFFTAG_SAMPLESPERPIXEL, 4);
    TIFFSetField(tiff, TIFFTAG_BITSPERSAMPLE, deep ? 16 : 8);
    TIFFSetField(tiff, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_SEPARATED);
    TIFFSetField(tiff, TIFFTAG_INKSET, INKSET_CMYK);
    TIFFSetField(tiff, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    TIFFSetField(tiff, TIFFTAG_ORIENTATION, ORIENTATION_TOPLEFT);
    TIFFSetField(tiff, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE);
    TIFFSetField(tiff, TIFFTAG_PREDICTOR, PREDICTOR_HORIZONTAL);
    TIFFSetField(tiff, TIFFTAG_ZIPQUALITY, 3);
    TIFFSetField(tiff, TIFFTAG_ROWSPERSTRIP, std::uint32_t(RowsPerStrip));
    TIFFSetField(tiff, TIFFTAG_SOFTWARE, "Marbler");
    // The printer's profile as given, so the print shop's software reads the numbers as meant.
    TIFFSetField(tiff, TIFFTAG_ICCPROFILE, std::uint32_t(profile.bytes.size()), profile.bytes.data());
    const std::string packet =
        genomeXmpPacket(options.genome.empty() ? serializeGenome(genome) : options.genome);
    TIFFSetField(tiff, TIFFTAG_XMLPACKET, std::uint32_t(packet.size()), packet.data());
    if (options.dpi) {
        TIFFSetField(tiff, TIFFTAG_XRESOLUTION, float(*options.dpi));
        TIFFSetField(tiff, TIFFTAG_YRESOLUTION, float(*options.dpi));
        TIFFSetField(tiff, TIFFTAG_RESOLUTIONUNIT, RESUNIT_INCH);
    }

    // Rendered a strip of the file's own rows at a time, so memory stays bounded at any size.
    const CpuRenderer renderer(genome);
    const std::size_t stripPixels = std::size_t(RowsPerStrip) * std::size_t(width);
    std::vector<std::uint8_t> rgb8, cmyk(stripPixels * 4 * (deep ? 2 : 1));
    std::vector<float> linear;
    std::vector<std::uint16_t> rgb16;
    if (deep) {
        linear.resize(stripPixels * 3);
        rgb16.resize(stripPixels * 3);
    } else {
        rgb8.resize(stripPixels * 3);
    }
    std::uint32_t strip = 0;
    for (int y0 = 0; y0 < height; y0 += RowsPerStrip, ++strip) {
        const int y1 = std::min(height, y0 + RowsPerStrip);
        RenderControl part;
        if (control) {
            part.cancel = control->cancel;
            if (control->progress)
                part.progress = [&, y0, y1](double f) { control->progress((y0 + f * (y1 - y0)) / height); };
        }
        const std::size_t pixels = std::size_t(y1 - y0) * std::size_t(width);
        if (deep) {
            // As the 16-bit RGB TIFF: sRGB encoded from the linear average, so the bits are real.
            renderer.renderRowsLinear(settings, y0, y1, linear.data(), &part);
            for (std::size_t k = 0; k < pixels * 3; ++k)
                rgb16[k] = std::uint16_t(
                    std::lround(linearToSrgb(std::clamp(double(linear[k]), 0.0, 1.0)) * 65535.0));
            conversion.convert(rgb16.data(), cmyk.data(), pixels);
        } else {
            renderer.renderRows(settings, y0, y1, rgb8.data(), &part);
            conversion.convert(rgb8.data(), cmyk.data(), pixels);
        }
        if (control && control->cancelled()) throw Cancelled();
        message.clear();
        if (TIFFWriteEncodedStrip(tiff, strip, cmyk.data(), tmsize_t(pixels * 4 * (deep ? 2 : 1))) < 0)
            failWrite(file, message.empty() ? "write failed" : message, errno);
    }
    message.clear();
    if (!TIFFFlush(tiff)) failWrite(file, message.empty() ? "write failed" : message, errno);
    TIFFClose(std::exchange(tiff, nullptr));
    atomic.commit();
}

} // namespace marbler
