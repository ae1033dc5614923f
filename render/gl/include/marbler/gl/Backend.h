#pragma once
/// Which back end renders: the GL shaders or the CPU kernel. On a machine without a GPU, Mesa
/// gives OpenGL through a software rasteriser (llvmpipe) that runs the shaders on the same cores
/// several times slower than the CPU kernel, so a context existing is not reason enough to use
/// it. The decision is a pure function of what the probe found and what the user asked for, so
/// the window, the command line's `doctor` and the tests share it.

#include <optional>
#include <string>
#include <string_view>

namespace marbler::gl {

/// What an offscreen OpenGL context looks like here.
struct GlProbe {
    bool available = false;
    std::string reason;                    ///< why none can be made (empty when available)
    std::string vendor, renderer, version; ///< GL_VENDOR, GL_RENDERER, GL_VERSION
    bool software = false;                 ///< the renderer is a software rasteriser (isSoftwareRenderer)
};

/// Makes an offscreen context (once per process; later calls return the cached answer) and reads
/// the driver's strings. Where no QGuiApplication exists one is made, as GlRenderer does. Never
/// throws: a failure is `available == false` with the reason.
GlProbe probeGl();

/// Whether a GL_RENDERER string names a software rasteriser (Mesa llvmpipe, softpipe, swrast,
/// "Software Rasterizer", Google SwiftShader, Microsoft Basic Render Driver, ...), case-insensitive.
bool isSoftwareRenderer(std::string_view rendererString);

/// What the user asked for: a setting in the window, MARBLER_RENDERER in the environment.
enum class BackendPreference { Auto, Gpu, Cpu };

/// "auto", "gpu" or "cpu" (case-insensitive, surrounding blanks ignored); nullopt otherwise.
std::optional<BackendPreference> parseBackendPreference(std::string_view text);
/// "auto", "gpu" or "cpu".
std::string_view backendPreferenceName(BackendPreference preference);

/// The environment variable that overrides the window's setting.
inline constexpr const char* BackendEnvironmentVariable = "MARBLER_RENDERER";
/// MARBLER_RENDERER's preference when it is set and valid; nullopt when unset. A value that is
/// none of auto, gpu, cpu is ignored, and `problem` (when given) says so.
std::optional<BackendPreference> environmentBackendPreference(std::string* problem = nullptr);

/// The decision and its reason, one clause for a status bar ("OpenGL is llvmpipe, a software
/// rasteriser: the CPU renderer is faster").
struct BackendChoice {
    bool useGl = false;
    std::string why;
};

/// Auto: hardware GL renders on the GPU; a software rasteriser or no GL, on the CPU. An
/// override wins, but Gpu without any GL falls back to the CPU and says why.
BackendChoice chooseBackend(const GlProbe& probe, BackendPreference preference);

} // namespace marbler::gl
