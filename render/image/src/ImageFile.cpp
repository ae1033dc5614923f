#include "marbler/ImageFile.h"

#include "ImageSink.h"
#include "marbler/AtomicFile.h"
#include "marbler/Error.h"
#include "marbler/ImageFormats.h"

#include <algorithm>
#include <vector>

namespace marbler {
namespace fs = std::filesystem;

struct ImageFileWriter::Impl {
    explicit Impl(const fs::path& file)
        : file(file) {}
    ~Impl() {
        sink.reset(); // closes the file before the AtomicFile removes it
    }
    AtomicFile file; // before sink: destroyed after it, so the sink closes the file first
    std::unique_ptr<detail::ImageSink> sink;
};

ImageFileWriter::ImageFileWriter(const fs::path& file, int width, int height, const ExportOptions& options)
    : mImpl(std::make_unique<Impl>(file)) {
    detail::SinkTarget target{
        mImpl->file.temporary().string(), lowerExtension(file), file.string(), width, height, options};
    mImpl->sink = detail::openBuiltinSink(target);
    if (!mImpl->sink) mImpl->sink = detail::imageIoModule().openSink(target);
}

ImageFileWriter::~ImageFileWriter() = default;

bool ImageFileWriter::linearFloat() const {
    return mImpl->sink->linearFloat();
}

void ImageFileWriter::writeRows(int y0, int y1, const void* rows) {
    mImpl->sink->writeRows(y0, y1, rows);
}

void ImageFileWriter::commit() {
    mImpl->sink->finish();
    mImpl->sink.reset();
    mImpl->file.commit();
}

int ImageFileWriter::stripRows(int width, int height) {
    const int most = std::max(16, (1 << 21) / std::max(1, width));
    return std::clamp((height + 7) / 8, 16, most);
}

void writeImage(const Image& image, const fs::path& file, const ExportOptions& options) {
    if (image.width < 1 || image.height < 1 ||
        image.rgb.size() != std::size_t(image.width) * std::size_t(image.height) * 3)
        throw RuntimeFailure("cannot write '" + file.string() + "': the image is empty or malformed");
    ImageFileWriter out(file, image.width, image.height, options);
    if (!out.linearFloat()) {
        out.writeRows(0, image.height, image.rgb.data());
    } else {
        const float* table = srgbToLinearTable();
        const int rows = ImageFileWriter::stripRows(image.width, image.height);
        std::vector<float> strip;
        for (int y0 = 0; y0 < image.height; y0 += rows) {
            int y1 = std::min(image.height, y0 + rows);
            strip.resize(std::size_t(y1 - y0) * std::size_t(image.width) * 3);
            const std::uint8_t* src = image.row(y0);
            for (std::size_t k = 0; k < strip.size(); ++k)
                strip[k] = table[src[k]];
            out.writeRows(y0, y1, strip.data());
        }
    }
    out.commit();
}

} // namespace marbler
