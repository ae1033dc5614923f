#include "GlContext.h"

#include <QGuiApplication>
#include <QSurfaceFormat>

#include <cstdio>
#include <cstdlib>

namespace marbler::gl::detail {
namespace {

bool nonEmptyEnv(const char* name) {
    const char* value = std::getenv(name);
    return value && *value;
}

/// Whether Qt can open a platform here without aborting the process: QGuiApplication calls
/// qFatal when its platform plugin cannot connect, so look before creating one.
bool platformUsable(std::string& why) {
    if (nonEmptyEnv("QT_QPA_PLATFORM")) return true;
    if (nonEmptyEnv("WAYLAND_DISPLAY")) return true;
    if (nonEmptyEnv("DISPLAY")) {
        std::string display = std::getenv("DISPLAY");
        // A local display ":N" has a socket; a remote one (host:N) cannot be checked cheaply.
        if (display.front() == ':') {
            std::string number = display.substr(1, display.find('.') - 1);
            std::error_code ec;
            if (!std::filesystem::exists("/tmp/.X11-unix/X" + number, ec)) {
                why = "DISPLAY=" + display + " names no running X server";
                return false;
            }
        }
        return true;
    }
    why = "no display: none of DISPLAY, WAYLAND_DISPLAY, QT_QPA_PLATFORM is set (run under xvfb-run)";
    return false;
}

/// The message handler of a QGuiApplication this library made itself: drops debug, info and
/// warning messages (e.g. "QStandardPaths: XDG_RUNTIME_DIR not set"), writes critical and fatal
/// ones as a single line on stderr.
void headlessMessages(QtMsgType type, const QMessageLogContext&, const QString& message) {
    if (type != QtCriticalMsg && type != QtFatalMsg) return;
    std::string line = message.toStdString();
    std::replace(line.begin(), line.end(), '\n', ' ');
    std::fprintf(stderr, "marbler: Qt: %s\n", line.c_str());
    std::fflush(stderr);
}

QSurfaceFormat requestedFormat(bool core43) {
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    if (core43) {
        format.setVersion(4, 3);
        format.setProfile(QSurfaceFormat::CoreProfile);
    }
    return format;
}

void tearDownAtExit() {
    LiveRenderers& live = liveRenderers();
    std::map<const void*, std::function<void()>> pending;
    {
        std::lock_guard lock(live.mutex);
        pending.swap(live.teardown);
    }
    for (auto& [key, teardown] : pending)
        teardown();
}

} // namespace

ContextParts makeContext(std::string& why) {
    ContextParts parts;
    if (!QGuiApplication::instance()) {
        if (QCoreApplication::instance()) {
            why = "a QCoreApplication without a GUI is running; OpenGL needs a QGuiApplication";
            return {};
        }
        if (!platformUsable(why)) return {};
        // Headless (the CLI, tests, benchmarks): Qt's chatter would break the contract of a clean
        // stderr on success, so only its critical and fatal messages get through, one line each.
        if (!nonEmptyEnv("MARBLER_QT_MESSAGES")) qInstallMessageHandler(headlessMessages);
        // Made once and never destroyed: a library cannot know when its caller's last GL use is,
        // and tearing Qt down in static destructors is unsafe.
        static int argc = 1;
        static char name[] = "marbler";
        static char* argv[] = {name, nullptr};
        new QGuiApplication(argc, argv);
    }
    for (bool core43 : {true, false}) {
        parts.context = std::make_unique<QOpenGLContext>();
        parts.context->setFormat(requestedFormat(core43));
        if (!parts.context->create()) continue;
        parts.surface = std::make_unique<QOffscreenSurface>();
        parts.surface->setFormat(parts.context->format());
        parts.surface->create();
        if (!parts.surface->isValid() || !parts.context->makeCurrent(parts.surface.get())) continue;
        auto [major, minor] = parts.context->format().version();
        if (major * 10 + minor < 43) {
            why = "OpenGL 4.3 is needed (shader storage buffers); the driver gives " + std::to_string(major) +
                  "." + std::to_string(minor) + " (" +
                  reinterpret_cast<const char*>(parts.context->functions()->glGetString(GL_RENDERER)) + ")";
            continue;
        }
        parts.gl = QOpenGLVersionFunctionsFactory::get<QOpenGLFunctions_4_3_Core>(parts.context.get());
        if (parts.gl && parts.gl->initializeOpenGLFunctions()) {
            why.clear();
            return parts;
        }
        why = "the OpenGL 4.3 core functions cannot be resolved";
    }
    if (why.empty())
        why = "no OpenGL context can be made on the \"" + QGuiApplication::platformName().toStdString() +
              "\" platform";
    return {};
}

LiveRenderers& liveRenderers() {
    static auto* live = new LiveRenderers; // never destroyed: used by the exit handler
    return *live;
}

void registerExitHandler() {
    static std::once_flag once;
    std::call_once(once, [] { std::atexit(tearDownAtExit); });
}

std::string glString(QOpenGLFunctions_4_3_Core* gl, GLenum name) {
    const auto* text = reinterpret_cast<const char*>(gl->glGetString(name));
    return text ? text : "";
}

} // namespace marbler::gl::detail
