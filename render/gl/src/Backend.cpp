#include "marbler/gl/Backend.h"

#include "GlContext.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdlib>

namespace marbler::gl {
namespace {

std::string lower(std::string_view text) {
    std::string result(text);
    std::transform(result.begin(), result.end(), result.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return result;
}

/// The renderer's name without the driver's details in brackets: "llvmpipe (LLVM 15.0.6, 256
/// bits)" reads "llvmpipe" in a status bar.
std::string shortRendererName(const std::string& renderer) {
    std::string name = renderer.substr(0, renderer.find(" ("));
    return name.empty() ? std::string("an unnamed renderer") : name;
}

} // namespace

bool isSoftwareRenderer(std::string_view rendererString) {
    // Lower-case fragments of the renderer strings of the software rasterisers in use: Mesa's
    // llvmpipe, softpipe and swrast (classic and "Software Rasterizer"), Google's SwiftShader
    // (also behind ANGLE), Microsoft's WARP ("Microsoft Basic Render Driver"), and the
    // fallback of Windows' GDI Generic OpenGL 1.1.
    static constexpr std::array fragments{
        "llvmpipe",   "softpipe", "swrast", "software rasterizer", "swiftshader", "microsoft basic render",
        "gdi generic"};
    const std::string text = lower(rendererString);
    return std::any_of(fragments.begin(), fragments.end(),
                       [&](const char* fragment) { return text.find(fragment) != std::string::npos; });
}

std::optional<BackendPreference> parseBackendPreference(std::string_view text) {
    const auto blank = [](unsigned char c) { return std::isspace(c) != 0; };
    while (!text.empty() && blank(text.front()))
        text.remove_prefix(1);
    while (!text.empty() && blank(text.back()))
        text.remove_suffix(1);
    const std::string word = lower(text);
    if (word == "auto") return BackendPreference::Auto;
    if (word == "gpu") return BackendPreference::Gpu;
    if (word == "cpu") return BackendPreference::Cpu;
    return std::nullopt;
}

std::string_view backendPreferenceName(BackendPreference preference) {
    switch (preference) {
    case BackendPreference::Auto:
        return "auto";
    case BackendPreference::Gpu:
        return "gpu";
    case BackendPreference::Cpu:
        return "cpu";
    }
    return "auto";
}

std::optional<BackendPreference> environmentBackendPreference(std::string* problem) {
    const char* value = std::getenv(BackendEnvironmentVariable);
    if (!value || !*value) return std::nullopt;
    std::optional<BackendPreference> preference = parseBackendPreference(value);
    if (!preference && problem)
        *problem =
            std::string(BackendEnvironmentVariable) + "=" + value + " is none of auto, gpu, cpu; ignored";
    return preference;
}

BackendChoice chooseBackend(const GlProbe& probe, BackendPreference preference) {
    const std::string noGl = "no OpenGL" + (probe.reason.empty() ? std::string() : ": " + probe.reason);
    switch (preference) {
    case BackendPreference::Cpu:
        return {false, "the CPU renderer was asked for"};
    case BackendPreference::Gpu:
        if (!probe.available) return {false, "the GPU renderer was asked for, but there is " + noGl};
        return {true, "the GPU renderer was asked for (OpenGL is " + shortRendererName(probe.renderer) +
                          (probe.software ? ", a software rasteriser)" : ")")};
    case BackendPreference::Auto:
        break;
    }
    if (!probe.available) return {false, noGl};
    if (probe.software)
        return {false, "OpenGL is " + shortRendererName(probe.renderer) +
                           ", a software rasteriser: the CPU renderer is faster"};
    return {true, "OpenGL is " + shortRendererName(probe.renderer) + ", a hardware GPU"};
}

namespace {

/// The one probe of the process: whether a context can be made, and the driver's strings.
GlProbe probeOnce() {
    GlProbe result;
    detail::ContextParts parts = detail::makeContext(result.reason);
    result.available = parts.gl != nullptr;
    if (result.available) {
        result.vendor = detail::glString(parts.gl, GL_VENDOR);
        result.renderer = detail::glString(parts.gl, GL_RENDERER);
        result.version = detail::glString(parts.gl, GL_VERSION);
        result.software = isSoftwareRenderer(result.renderer);
    }
    if (parts.context) parts.context->doneCurrent();
    if (result.available) detail::registerExitHandler();
    return result;
}

} // namespace

GlProbe probeGl() {
    static std::once_flag once;
    static GlProbe result;
    std::call_once(once, [] { result = probeOnce(); });
    return result;
}

} // namespace marbler::gl
