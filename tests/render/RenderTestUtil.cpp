#include "RenderTestUtil.h"

#include "TestUtil.h"
#include "marbler/GenomeIO.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>

namespace marbler::test {

nlohmann::json loadConformance(const std::string& name) {
    return nlohmann::json::parse(readFile(dataDir() / "conformance" / name));
}

Genome genomeOf(const nlohmann::json& file, const std::string& name) {
    return parseGenome(file.at("genome").dump(), name);
}

Image readImage8(const std::filesystem::path& file) {
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) throw std::runtime_error("cannot read " + file.string() + ": " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    Image image;
    image.width = spec.width;
    image.height = spec.height;
    std::vector<std::uint8_t> all(std::size_t(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, all.data()))
        throw std::runtime_error("cannot read " + file.string() + ": " + in->geterror());
    image.rgb.resize(std::size_t(spec.width) * spec.height * 3);
    for (std::size_t p = 0; p < std::size_t(spec.width) * spec.height; ++p)
        for (int c = 0; c < 3; ++c)
            image.rgb[p * 3 + c] = all[p * spec.nchannels + (spec.nchannels >= 3 ? c : 0)];
    return image;
}

ImageDiff compareImages(const Image& a, const Image& b, int tolerance) {
    ImageDiff diff;
    if (a.width != b.width || a.height != b.height) {
        diff.maxDifference = 256;
        return diff;
    }
    std::size_t within = 0, pixels = std::size_t(a.width) * a.height;
    for (std::size_t p = 0; p < pixels; ++p) {
        int worst = 0;
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::abs(int(a.rgb[p * 3 + c]) - int(b.rgb[p * 3 + c])));
        diff.maxDifference = std::max(diff.maxDifference, worst);
        within += worst <= tolerance;
    }
    diff.shareWithin = pixels ? double(within) / double(pixels) : 1.0;
    return diff;
}

} // namespace marbler::test
