#pragma once
/// Internal to render/gl: the offscreen OpenGL contexts of the back end (a renderer's, the
/// probe's), the QGuiApplication a headless process needs for them, and the exit handler that
/// tears renderers down before the driver's own exit handlers run.

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions_4_3_Core>

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace marbler::gl::detail {

/// A context (4.3 core, else whatever the driver gives if that is 4.3 or newer) on an offscreen
/// surface, current. Empty `why` on success.
struct ContextParts {
    std::unique_ptr<QOpenGLContext> context;
    std::unique_ptr<QOffscreenSurface> surface;
    QOpenGLFunctions_4_3_Core* gl = nullptr;
};

/// Makes a context, and first the QGuiApplication it needs where none runs (once, never
/// destroyed; Qt's chatter silenced unless MARBLER_QT_MESSAGES is set). On failure `gl` is null
/// and `why` says why.
ContextParts makeContext(std::string& why);

/// A GL string (GL_VENDOR, ...), empty when the driver gives none.
std::string glString(QOpenGLFunctions_4_3_Core* gl, GLenum name);

/// Renderers still alive, torn down by an exit handler: a renderer held in a static would
/// otherwise be destroyed after the driver's own exit handlers (Mesa stops its threads at exit)
/// and crash the process on its way out. The handler is registered after the first context is
/// made, so it runs before the driver's handlers and before the destructors of statics made
/// earlier.
struct LiveRenderers {
    std::mutex mutex;
    std::map<const void*, std::function<void()>> teardown;
};
LiveRenderers& liveRenderers();
/// Registers the exit handler (once).
void registerExitHandler();

} // namespace marbler::gl::detail
