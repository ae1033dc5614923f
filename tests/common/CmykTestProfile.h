#pragma once
// ICC profiles made in the tests with LittleCMS's own API (issue 29's CMYK TIFF): a small CMYK
// output (printer) profile of our own, so no profile of unknown licence is committed, and the
// profiles the export must refuse. Header-only; the test links lcms2.

#include <lcms2.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace marbler::test {

/// The bytes of a profile LittleCMS holds (closed afterwards).
inline std::vector<unsigned char> profileBytes(cmsHPROFILE profile) {
    cmsUInt32Number size = 0;
    if (!cmsSaveProfileToMem(profile, nullptr, &size)) throw std::runtime_error("cmsSaveProfileToMem");
    std::vector<unsigned char> bytes(size);
    cmsSaveProfileToMem(profile, bytes.data(), &size);
    cmsCloseProfile(profile);
    return bytes;
}

namespace cmyk_detail {
/// Lab (PCS) to RGB and back, through LittleCMS's own profiles, for the samplers below.
struct Transforms {
    cmsHTRANSFORM labToRgb, rgbToLab;
    Transforms() {
        cmsHPROFILE lab = cmsCreateLab4Profile(nullptr), srgb = cmsCreate_sRGBProfile();
        labToRgb = cmsCreateTransform(lab, TYPE_Lab_16, srgb, TYPE_RGB_16, INTENT_PERCEPTUAL, 0);
        rgbToLab = cmsCreateTransform(srgb, TYPE_RGB_16, lab, TYPE_Lab_16, INTENT_PERCEPTUAL, 0);
        cmsCloseProfile(lab);
        cmsCloseProfile(srgb);
    }
};
inline Transforms& transforms() {
    static Transforms t;
    return t;
}
/// A simple press: CMY the complement of RGB, half the grey component replaced by black.
inline cmsInt32Number labToCmyk(const cmsUInt16Number in[], cmsUInt16Number out[], void*) {
    cmsUInt16Number rgb[3];
    cmsDoTransform(transforms().labToRgb, in, rgb, 1);
    const int c = 65535 - rgb[0], m = 65535 - rgb[1], y = 65535 - rgb[2];
    const int k = std::min({c, m, y}) / 2;
    out[0] = cmsUInt16Number(c - k);
    out[1] = cmsUInt16Number(m - k);
    out[2] = cmsUInt16Number(y - k);
    out[3] = cmsUInt16Number(k);
    return 1;
}
inline cmsInt32Number cmykToLab(const cmsUInt16Number in[], cmsUInt16Number out[], void*) {
    cmsUInt16Number rgb[3];
    for (int i = 0; i < 3; ++i)
        rgb[i] = cmsUInt16Number(std::max(0, 65535 - int(in[i]) - int(in[3])));
    cmsDoTransform(transforms().rgbToLab, rgb, out, 1);
    return 1;
}
} // namespace cmyk_detail

/// A CMYK output profile (ICC v4, Lab connection space, AToB0 and BToA0 tables sampled from a
/// simple press model), described as `description`.
inline std::vector<unsigned char> makeCmykProfile(const char* description = "Marbler test press CMYK") {
    cmsHPROFILE profile = cmsCreateProfilePlaceholder(nullptr);
    cmsSetProfileVersion(profile, 4.3);
    cmsSetDeviceClass(profile, cmsSigOutputClass);
    cmsSetColorSpace(profile, cmsSigCmykData);
    cmsSetPCS(profile, cmsSigLabData);
    cmsSetHeaderRenderingIntent(profile, INTENT_PERCEPTUAL);
    cmsPipeline* toCmyk = cmsPipelineAlloc(nullptr, 3, 4);
    cmsStage* clut = cmsStageAllocCLut16bit(nullptr, 17, 3, 4, nullptr);
    cmsStageSampleCLut16bit(clut, cmyk_detail::labToCmyk, nullptr, 0);
    // lutBtoAType's form: B curves, CLUT, A curves (identity curves around the table).
    cmsPipelineInsertStage(toCmyk, cmsAT_END, cmsStageAllocToneCurves(nullptr, 3, nullptr));
    cmsPipelineInsertStage(toCmyk, cmsAT_END, clut);
    cmsPipelineInsertStage(toCmyk, cmsAT_END, cmsStageAllocToneCurves(nullptr, 4, nullptr));
    cmsWriteTag(profile, cmsSigBToA0Tag, toCmyk);
    cmsPipelineFree(toCmyk);
    cmsPipeline* toLab = cmsPipelineAlloc(nullptr, 4, 3);
    clut = cmsStageAllocCLut16bit(nullptr, 9, 4, 3, nullptr);
    cmsStageSampleCLut16bit(clut, cmyk_detail::cmykToLab, nullptr, 0);
    // lutAtoBType's form: A curves, CLUT, B curves.
    cmsPipelineInsertStage(toLab, cmsAT_END, cmsStageAllocToneCurves(nullptr, 4, nullptr));
    cmsPipelineInsertStage(toLab, cmsAT_END, clut);
    cmsPipelineInsertStage(toLab, cmsAT_END, cmsStageAllocToneCurves(nullptr, 3, nullptr));
    cmsWriteTag(profile, cmsSigAToB0Tag, toLab);
    cmsPipelineFree(toLab);
    cmsWriteTag(profile, cmsSigMediaWhitePointTag, cmsD50_XYZ());
    cmsMLU* text = cmsMLUalloc(nullptr, 1);
    cmsMLUsetASCII(text, "en", "US", description);
    cmsWriteTag(profile, cmsSigProfileDescriptionTag, text);
    cmsMLUfree(text);
    return profileBytes(profile);
}

/// LittleCMS's sRGB display profile: an ICC profile, but not a printer's.
inline std::vector<unsigned char> makeDisplayProfile() {
    return profileBytes(cmsCreate_sRGBProfile());
}

/// An output profile for RGB: a printer's, but not CMYK.
inline std::vector<unsigned char> makeRgbOutputProfile() {
    cmsHPROFILE profile = cmsCreate_sRGBProfile();
    cmsSetDeviceClass(profile, cmsSigOutputClass);
    return profileBytes(profile);
}

inline void writeBytes(const std::filesystem::path& file, const std::vector<unsigned char>& bytes) {
    std::ofstream(file, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

/// What LittleCMS itself makes of sRGB pixels with the profile (8 or 16 bits a sample): the
/// reference the written TIFF is held to.
template <typename T>
std::vector<T> lcmsCmykOf(const std::vector<T>& rgb, const std::vector<unsigned char>& profile,
                          cmsUInt32Number intent = INTENT_PERCEPTUAL) {
    cmsHPROFILE srgb = cmsCreate_sRGBProfile();
    cmsHPROFILE printer = cmsOpenProfileFromMem(profile.data(), cmsUInt32Number(profile.size()));
    const bool deep = sizeof(T) == 2;
    cmsHTRANSFORM t = cmsCreateTransform(srgb, deep ? TYPE_RGB_16 : TYPE_RGB_8, printer,
                                         deep ? TYPE_CMYK_16 : TYPE_CMYK_8, intent, 0);
    std::vector<T> out(rgb.size() / 3 * 4);
    cmsDoTransform(t, rgb.data(), out.data(), cmsUInt32Number(rgb.size() / 3));
    cmsDeleteTransform(t);
    cmsCloseProfile(printer);
    cmsCloseProfile(srgb);
    return out;
}

} // namespace marbler::test
