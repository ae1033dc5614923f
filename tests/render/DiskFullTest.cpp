// A full disk said in plain words (issue 29: "TIFFAppendToStrip: Write error at scanline 3008",
// "Write Error", "No space left on device"). The image writers are driven into /dev/full, whose
// every write fails with ENOSPC as on a full disk, so libpng's and libtiff's own error paths run;
// the name shown is the one the user chose (the writers write a temporary beside it).

#include "ImageSink.h"
#include "marbler/AtomicFile.h"
#include "marbler/Error.h"

#include <gtest/gtest.h>

#include <cerrno>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace marbler {
namespace {

namespace fs = std::filesystem;

/// Writes a `width` x `height` image of `extension` into /dev/full; the message of the failure.
std::string failureWriting(const std::string& extension, int bits = 8) {
    detail::SinkTarget target;
    target.file = "/dev/full";
    target.extension = extension;
    target.displayName = "/home/someone/prints/harbour green" + extension;
    target.width = 512;
    target.height = 512;
    target.options.bitsPerSample = bits;
    try {
        std::unique_ptr<detail::ImageSink> sink = detail::openBuiltinSink(target);
        EXPECT_NE(sink, nullptr) << extension;
        if (!sink) return {};
        const std::size_t values = std::size_t(target.width) * 3 * 64;
        std::vector<unsigned char> bytes(sink->linearFloat() ? values * sizeof(float) : values);
        // Noise, so compression cannot make it small enough to sit in a buffer.
        unsigned state = 12345;
        for (unsigned char& b : bytes) {
            state = state * 1103515245u + 12345u;
            b = static_cast<unsigned char>(state >> 16);
        }
        if (sink->linearFloat()) {
            auto* f = reinterpret_cast<float*>(bytes.data());
            for (std::size_t k = 0; k < values; ++k)
                f[k] = float(bytes[k] % 255) / 255.0f;
        }
        for (int y = 0; y < target.height; y += 64)
            sink->writeRows(y, y + 64, bytes.data());
        sink->finish();
    } catch (const RuntimeFailure& e) {
        return e.what();
    }
    ADD_FAILURE() << extension << ": writing into /dev/full did not fail";
    return {};
}

TEST(DiskFull, TheImageWritersSayTheDiskIsFullAndWhere) {
    if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
    for (const auto& [extension, bits] :
         std::vector<std::pair<std::string, int>>{{".png", 8}, {".tif", 8}, {".tif", 16}, {".ppm", 8}}) {
        const std::string message = failureWriting(extension, bits);
        EXPECT_NE(message.find("the disk is full"), std::string::npos) << extension << ": " << message;
        EXPECT_NE(message.find("harbour green" + extension), std::string::npos) << message;
        EXPECT_NE(message.find("/home/someone/prints"), std::string::npos) << "the folder: " << message;
        EXPECT_EQ(message.find("Write error"), std::string::npos) << message;
        EXPECT_EQ(message.find("Write Error"), std::string::npos) << message;
    }
}

TEST(DiskFull, EveryAtomicWriteSaysItToo) {
    // The SVG, genomes and sessions go through AtomicFile, whose writes report errno the same way.
    const std::string full = writeFailureMessage("/home/someone/prints/sheet.svg", ENOSPC);
    EXPECT_NE(full.find("the disk is full"), std::string::npos) << full;
    EXPECT_NE(full.find("/home/someone/prints/sheet.svg"), std::string::npos) << full;
    EXPECT_NE(full.find("free some space in /home/someone/prints"), std::string::npos) << full;
    EXPECT_NE(writeFailureMessage("/x/sheet.svg", EDQUOT).find("the disk is full"), std::string::npos);
    // Other errors keep the system's words.
    const std::string denied = writeFailureMessage("/x/sheet.svg", EACCES);
    EXPECT_EQ(denied.find("disk is full"), std::string::npos) << denied;
    EXPECT_NE(denied.find("cannot write /x/sheet.svg"), std::string::npos) << denied;
}

} // namespace
} // namespace marbler
