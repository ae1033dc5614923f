#include "GlTestUtil.h"

#include <QImage>

#include <cstdlib>
#include <cstring>
#include <memory>

namespace marbler::test {

gl::GlRenderer* glRenderer() {
    static std::unique_ptr<gl::GlRenderer> renderer;
    if (!renderer && gl::GlRenderer::available()) renderer = std::make_unique<gl::GlRenderer>();
    return renderer.get();
}

bool glRequired() {
    const char* value = std::getenv("MARBLER_REQUIRE_GL");
    return value && std::strcmp(value, "1") == 0;
}

void savePng(const Image& image, const std::filesystem::path& file) {
    QImage out(image.rgb.data(), image.width, image.height, image.width * 3, QImage::Format_RGB888);
    out.save(QString::fromStdString(file.string()));
}

Image loadPng(const std::filesystem::path& file) {
    Image image;
    QImage in;
    if (!in.load(QString::fromStdString(file.string()))) return image;
    in = in.convertToFormat(QImage::Format_RGB888);
    image.width = in.width();
    image.height = in.height();
    image.rgb.resize(std::size_t(image.width) * std::size_t(image.height) * 3);
    for (int y = 0; y < image.height; ++y)
        std::memcpy(image.row(y), in.constScanLine(y), std::size_t(image.width) * 3);
    return image;
}

} // namespace marbler::test
