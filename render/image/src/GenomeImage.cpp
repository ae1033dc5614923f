// Genomes inside images: finding the genome text in a PNG's text chunks (libpng) or a TIFF's
// XMP packet (libtiff), from a file or from memory, without OpenImageIO. Every input here may
// be hostile: sizes are capped before anything is allocated, and libpng's and libtiff's errors
// become one-line InputErrors naming the image.

#include "marbler/GenomeImage.h"

#include "marbler/Error.h"
#include "marbler/GenomeIO.h"
#include "marbler/ImageFormats.h"
#include "marbler/OneLine.h"

#include <png.h>
#include <tiffio.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csetjmp>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>

namespace marbler {
namespace {

/// The most a PNG chunk or decompressed text may hold: a genome of MaxFileBytes with room for
/// the chunk's keyword and language fields. libpng refuses a larger chunk before allocating it.
constexpr std::size_t MaxChunkBytes = MaxFileBytes + 4096;
/// The most libtiff may allocate at once while reading a TIFF's directory (tag arrays, the XMP
/// packet): enough for any genome, far below what a hostile count could ask for.
constexpr std::size_t MaxTiffAllocation = 4 * MaxFileBytes;

/// The most pixel data decoded to reach text chunks that follow a PNG's image data.
constexpr std::size_t MaxScannedPixelBytes = std::size_t(1) << 30;

/// Bytes read in order, from a file or from memory, with seeking for libtiff.
class ByteSource {
public:
    virtual ~ByteSource() = default;
    /// Reads up to `size` bytes; returns how many were read (fewer at the end).
    virtual std::size_t read(void* data, std::size_t size) = 0;
    /// Moves to an absolute offset; false when it cannot.
    virtual bool seek(std::uint64_t offset) = 0;
    virtual std::uint64_t tell() const = 0;
    virtual std::uint64_t size() const = 0;
};

class FileSource final : public ByteSource {
public:
    FileSource(const std::filesystem::path& file, const std::string& name) {
        mFile = std::fopen(file.c_str(), "rb");
        if (!mFile) throw InputError(name + ": cannot read: " + std::strerror(errno));
        if (std::fseek(mFile, 0, SEEK_END) == 0) {
            long end = std::ftell(mFile);
            mSize = end < 0 ? 0 : std::uint64_t(end);
        }
        std::fseek(mFile, 0, SEEK_SET);
    }
    ~FileSource() override { std::fclose(mFile); }
    FileSource(const FileSource&) = delete;
    FileSource& operator=(const FileSource&) = delete;

    std::size_t read(void* data, std::size_t size) override {
        std::size_t got = std::fread(data, 1, size, mFile);
        mOffset += got;
        return got;
    }
    bool seek(std::uint64_t offset) override {
        if (offset > std::uint64_t(INT64_MAX) || fseeko(mFile, off_t(offset), SEEK_SET) != 0) return false;
        mOffset = offset;
        return true;
    }
    std::uint64_t tell() const override { return mOffset; }
    std::uint64_t size() const override { return mSize; }

private:
    std::FILE* mFile = nullptr;
    std::uint64_t mSize = 0, mOffset = 0;
};

class MemorySource final : public ByteSource {
public:
    explicit MemorySource(std::span<const unsigned char> bytes)
        : mBytes(bytes) {}
    std::size_t read(void* data, std::size_t size) override {
        std::size_t got =
            mOffset >= mBytes.size() ? 0 : std::min<std::size_t>(size, mBytes.size() - std::size_t(mOffset));
        if (got) std::memcpy(data, mBytes.data() + mOffset, got);
        mOffset += got;
        return got;
    }
    bool seek(std::uint64_t offset) override {
        mOffset = offset; // past the end is allowed; reads there return nothing
        return true;
    }
    std::uint64_t tell() const override { return mOffset; }
    std::uint64_t size() const override { return mBytes.size(); }

private:
    std::span<const unsigned char> mBytes;
    std::uint64_t mOffset = 0;
};

/// tEXt and zTXt chunks are Latin-1; the genome parser wants UTF-8.
std::string latin1ToUtf8(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (unsigned char c : text) {
        if (c < 0x80) {
            out += char(c);
        } else {
            out += char(0xc0 | (c >> 6));
            out += char(0x80 | (c & 0x3f));
        }
    }
    return out;
}

// --- PNG --------------------------------------------------------------------------------------

/// libpng reports errors by longjmp: every libpng call is made inside pngCall, from frames with
/// no C++ objects to unwind, and the message is kept for the exception thrown afterwards.
struct PngReader {
    png_structp png = nullptr;
    png_infop info = nullptr;
    png_infop endInfo = nullptr;
    ByteSource* source = nullptr;
    char message[256] = {};
    /// The first warning about a text chunk (libpng drops such a chunk and goes on): said when
    /// no genome is found, since the genome may have been in it.
    char textWarning[256] = {};
    ~PngReader() {
        if (png) png_destroy_read_struct(&png, info ? &info : nullptr, endInfo ? &endInfo : nullptr);
    }
};

void pngReadError(png_structp png, png_const_charp message) {
    auto* reader = static_cast<PngReader*>(png_get_error_ptr(png));
    std::snprintf(reader->message, sizeof reader->message, "%s", message);
    png_longjmp(png, 1);
}

void pngReadWarning(png_structp png, png_const_charp message) {
    auto* reader = static_cast<PngReader*>(png_get_error_ptr(png));
    const bool aboutText = std::strncmp(message, "iTXt", 4) == 0 || std::strncmp(message, "zTXt", 4) == 0 ||
                           std::strncmp(message, "tEXt", 4) == 0;
    if (aboutText && reader->textWarning[0] == '\0')
        std::snprintf(reader->textWarning, sizeof reader->textWarning, "%s", message);
}

void pngReadData(png_structp png, png_bytep data, size_t size) {
    auto* reader = static_cast<PngReader*>(png_get_io_ptr(png));
    if (reader->source->read(data, size) != size) png_error(png, "the file ends too early (truncated)");
}

template <typename Body> bool pngCall(PngReader& reader, Body body) {
    if (setjmp(png_jmpbuf(reader.png))) return false;
    body();
    return true;
}

/// The genome among a PNG info's text chunks.
std::optional<std::string> genomeInText(png_structp png, png_infop info) {
    png_textp texts = nullptr;
    int count = png_get_text(png, info, &texts, nullptr);
    for (int i = 0; i < count; ++i) {
        const png_text& t = texts[i];
        if (!t.key || std::strcmp(t.key, PngGenomeKeyword) != 0 || !t.text) continue;
        if (t.compression == PNG_ITXT_COMPRESSION_NONE || t.compression == PNG_ITXT_COMPRESSION_zTXt)
            return std::string(t.text, t.itxt_length);
        return latin1ToUtf8(std::string_view(t.text, t.text_length));
    }
    return std::nullopt;
}

std::optional<std::string> readPngGenome(ByteSource& source, const std::string& name) {
    PngReader reader;
    reader.source = &source;
    auto fail = [&](const char* message) {
        throw InputError(name + ": cannot read the PNG: " + oneLine(message));
    };
    reader.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &reader, pngReadError, pngReadWarning);
    if (!reader.png) fail("out of memory");
    reader.info = png_create_info_struct(reader.png);
    reader.endInfo = png_create_info_struct(reader.png);
    if (!reader.info || !reader.endInfo) fail("out of memory");
    bool ok = pngCall(reader, [&] {
        png_set_read_fn(reader.png, &reader, pngReadData);
        // A chunk larger than any genome is refused before it is allocated; decompressed text
        // is held to the same limit.
        png_set_chunk_malloc_max(reader.png, MaxChunkBytes);
        // A damaged chunk is an error, not a chunk silently dropped: the genome may be in it.
        png_set_crc_action(reader.png, PNG_CRC_ERROR_QUIT, PNG_CRC_ERROR_QUIT);
        png_read_info(reader.png, reader.info);
    });
    if (!ok) fail(reader.message);
    // Marbler writes the genome before the image data, where it is found without decoding a
    // pixel.
    if (std::optional<std::string> text = genomeInText(reader.png, reader.info)) return text;

    // Other programs may move text chunks after the image data when they save a file again;
    // reaching them means decoding the rows, one at a time.
    int passes = 1;
    ok = pngCall(reader, [&] {
        passes = png_set_interlace_handling(reader.png);
        png_read_update_info(reader.png, reader.info);
    });
    if (!ok) fail(reader.message);
    const std::size_t rowBytes = png_get_rowbytes(reader.png, reader.info);
    const png_uint_32 height = png_get_image_height(reader.png, reader.info);
    // Deflate packs a thousand bytes into one, so a small hostile file can claim gigabytes of
    // rows: past MaxScannedPixelBytes the rows are not decoded and only the chunks before the
    // image data count.
    if (double(rowBytes) * double(height) * double(passes) > double(MaxScannedPixelBytes))
        return std::nullopt;
    std::vector<png_byte> row(std::max<std::size_t>(rowBytes, 1));
    png_bytep rowData = row.data();
    ok = pngCall(reader, [&] {
        for (int pass = 0; pass < passes; ++pass)
            for (png_uint_32 y = 0; y < height; ++y)
                png_read_row(reader.png, rowData, nullptr);
        png_read_end(reader.png, reader.endInfo);
    });
    if (!ok) fail(reader.message);
    if (std::optional<std::string> text = genomeInText(reader.png, reader.endInfo)) return text;
    if (reader.textWarning[0] != '\0')
        throw InputError(
            name + " is an image without a readable Marbler genome in it (a text chunk could not be read: " +
            oneLine(reader.textWarning) + ")");
    return std::nullopt;
}

// --- TIFF -------------------------------------------------------------------------------------

struct TiffReader {
    ByteSource* source = nullptr;
    std::string error; ///< the first error libtiff reported
};

int tiffReadError(TIFF*, void* data, const char* module, const char* format, va_list args) {
    auto* reader = static_cast<TiffReader*>(data);
    if (reader->error.empty()) {
        char text[512];
        std::vsnprintf(text, sizeof text, format, args);
        reader->error = module && *module ? std::string(module) + ": " + text : text;
    }
    return 1; // handled: nothing reaches the process-wide handler
}

int tiffReadWarning(TIFF*, void*, const char*, const char*, va_list) {
    return 1;
}

tmsize_t tiffRead(thandle_t handle, void* data, tmsize_t size) {
    auto* reader = static_cast<TiffReader*>(handle);
    return size < 0 ? -1 : tmsize_t(reader->source->read(data, std::size_t(size)));
}
tmsize_t tiffWrite(thandle_t, void*, tmsize_t) {
    return -1;
}
toff_t tiffSeek(thandle_t handle, toff_t offset, int whence) {
    ByteSource& source = *static_cast<TiffReader*>(handle)->source;
    std::uint64_t target = offset;
    if (whence == SEEK_CUR)
        target = source.tell() + offset;
    else if (whence == SEEK_END)
        target = source.size() + offset;
    return source.seek(target) ? target : toff_t(-1);
}
int tiffClose(thandle_t) {
    return 0;
}
toff_t tiffSize(thandle_t handle) {
    return static_cast<TiffReader*>(handle)->source->size();
}
int tiffMap(thandle_t, void**, toff_t*) {
    return 0;
}
void tiffUnmap(thandle_t, void*, toff_t) {}

std::optional<std::string> readTiffGenome(ByteSource& source, const std::string& name) {
    TiffReader reader;
    reader.source = &source;
    std::unique_ptr<TIFFOpenOptions, void (*)(TIFFOpenOptions*)> options(TIFFOpenOptionsAlloc(),
                                                                         TIFFOpenOptionsFree);
    if (!options) throw InputError(name + ": cannot read the TIFF: out of memory");
    TIFFOpenOptionsSetMaxSingleMemAlloc(options.get(), tmsize_t(MaxTiffAllocation));
    TIFFOpenOptionsSetErrorHandlerExtR(options.get(), tiffReadError, &reader);
    TIFFOpenOptionsSetWarningHandlerExtR(options.get(), tiffReadWarning, &reader);
    // "m": no memory mapping, every byte comes through the source.
    TIFF* tiff = TIFFClientOpenExt(name.c_str(), "rm", &reader, tiffRead, tiffWrite, tiffSeek, tiffClose,
                                   tiffSize, tiffMap, tiffUnmap, options.get());
    if (!tiff)
        throw InputError(name + ": cannot read the TIFF: " +
                         oneLine(reader.error.empty() ? "not a readable TIFF file" : reader.error));
    std::unique_ptr<TIFF, void (*)(TIFF*)> closer(tiff, TIFFClose);
    std::uint32_t count = 0;
    const void* packet = nullptr;
    if (TIFFGetField(tiff, TIFFTAG_XMLPACKET, &count, &packet) && packet) {
        if (count > MaxTiffAllocation)
            throw InputError(name + ": cannot read the TIFF: its XMP packet is larger than " +
                             std::to_string(MaxTiffAllocation / (1024 * 1024)) + " MiB");
        if (std::optional<std::string> text =
                genomeFromXmp(std::string_view(static_cast<const char*>(packet), count)))
            return text;
    }
    // A genome that a tool moved into the description (as some do with XMP they do not keep).
    const char* description = nullptr;
    if (TIFFGetField(tiff, TIFFTAG_IMAGEDESCRIPTION, &description) && description) {
        std::string_view text(description);
        if (text.find("\"marbler-genome\"") != std::string_view::npos &&
            text.find_first_not_of(" \t\r\n") != std::string_view::npos &&
            text[text.find_first_not_of(" \t\r\n")] == '{')
            return std::string(text);
    }
    if (!reader.error.empty()) throw InputError(name + ": cannot read the TIFF: " + oneLine(reader.error));
    return std::nullopt;
}

std::optional<std::string> readFromSource(ByteSource& source, ImageKind kind, const std::string& name) {
    if (kind == ImageKind::Png) return readPngGenome(source, name);
    if (kind == ImageKind::Tiff) return readTiffGenome(source, name);
    throw InputError(name + " is a " + imageKindName(kind) +
                     " image; only PNG and TIFF images carry a Marbler genome");
}

// --- XMP --------------------------------------------------------------------------------------

void appendUtf8(std::string& out, std::uint32_t code) {
    if (code < 0x80) {
        out += char(code);
    } else if (code < 0x800) {
        out += char(0xc0 | (code >> 6));
        out += char(0x80 | (code & 0x3f));
    } else if (code < 0x10000) {
        out += char(0xe0 | (code >> 12));
        out += char(0x80 | ((code >> 6) & 0x3f));
        out += char(0x80 | (code & 0x3f));
    } else {
        out += char(0xf0 | (code >> 18));
        out += char(0x80 | ((code >> 12) & 0x3f));
        out += char(0x80 | ((code >> 6) & 0x3f));
        out += char(0x80 | (code & 0x3f));
    }
}

/// XML character data with its entities and CDATA sections decoded. An entity it does not know
/// is kept as written (the genome parser then says where the text is wrong).
std::string decodeXmlText(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        if (text.substr(i, 9) == "<![CDATA[") {
            std::size_t end = text.find("]]>", i + 9);
            if (end == std::string_view::npos) end = text.size();
            out.append(text.substr(i + 9, end - i - 9));
            i = std::min(text.size(), end + 3);
            continue;
        }
        if (text[i] != '&') {
            out += text[i++];
            continue;
        }
        std::size_t semi = text.find(';', i);
        std::string_view entity = semi == std::string_view::npos || semi - i > 12
                                      ? std::string_view()
                                      : text.substr(i + 1, semi - i - 1);
        std::uint32_t code = 0;
        bool known = true;
        if (entity == "lt")
            code = '<';
        else if (entity == "gt")
            code = '>';
        else if (entity == "amp")
            code = '&';
        else if (entity == "quot")
            code = '"';
        else if (entity == "apos")
            code = '\'';
        else if (entity.size() > 1 && entity[0] == '#') {
            const bool hex = entity[1] == 'x' || entity[1] == 'X';
            std::string_view digits = entity.substr(hex ? 2 : 1);
            known = !digits.empty();
            for (char c : digits) {
                int v = c >= '0' && c <= '9'          ? c - '0'
                        : hex && c >= 'a' && c <= 'f' ? c - 'a' + 10
                        : hex && c >= 'A' && c <= 'F' ? c - 'A' + 10
                                                      : -1;
                if (v < 0 || code > 0x10ffff) {
                    known = false;
                    break;
                }
                code = code * (hex ? 16 : 10) + std::uint32_t(v);
            }
            known = known && code <= 0x10ffff;
        } else {
            known = false;
        }
        if (!known) {
            out += text[i++];
            continue;
        }
        appendUtf8(out, code);
        i = semi + 1;
    }
    return out;
}

bool isXmlSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

bool isNameChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' ||
           static_cast<unsigned char>(c) >= 0x80;
}

/// The prefixes an XMP packet binds to XmpNamespace (`xmlns:PREFIX="..."`).
std::vector<std::string> prefixesOf(std::string_view xml) {
    std::vector<std::string> prefixes;
    for (std::size_t at = xml.find("xmlns:"); at != std::string_view::npos; at = xml.find("xmlns:", at + 6)) {
        std::size_t end = at + 6;
        while (end < xml.size() && isNameChar(xml[end]))
            ++end;
        std::string prefix(xml.substr(at + 6, end - at - 6));
        while (end < xml.size() && isXmlSpace(xml[end]))
            ++end;
        if (end >= xml.size() || xml[end] != '=') continue;
        ++end;
        while (end < xml.size() && isXmlSpace(xml[end]))
            ++end;
        if (end >= xml.size() || (xml[end] != '"' && xml[end] != '\'')) continue;
        const char quote = xml[end];
        std::size_t close = xml.find(quote, end + 1);
        if (close == std::string_view::npos) break;
        if (!prefix.empty() && xml.substr(end + 1, close - end - 1) == XmpNamespace)
            prefixes.push_back(prefix);
    }
    return prefixes;
}

} // namespace

ImageKind imageKindOf(std::span<const unsigned char> head) {
    auto starts = [&](std::initializer_list<unsigned char> magic, std::size_t at = 0) {
        if (head.size() < at + magic.size()) return false;
        return std::equal(magic.begin(), magic.end(), head.begin() + std::ptrdiff_t(at));
    };
    if (starts({0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'})) return ImageKind::Png;
    if (starts({'I', 'I', 42, 0}) || starts({'M', 'M', 0, 42}) || starts({'I', 'I', 43, 0}) ||
        starts({'M', 'M', 0, 43}))
        return ImageKind::Tiff;
    if (starts({0xff, 0xd8, 0xff})) return ImageKind::Jpeg;
    if (starts({'G', 'I', 'F', '8'})) return ImageKind::Gif;
    if (starts({'R', 'I', 'F', 'F'}) && starts({'W', 'E', 'B', 'P'}, 8)) return ImageKind::Webp;
    if (starts({0x76, 0x2f, 0x31, 0x01})) return ImageKind::Exr;
    if (starts({'B', 'M'}) && head.size() >= 14 && head[6] == 0 && head[7] == 0 && head[8] == 0 &&
        head[9] == 0)
        return ImageKind::Bmp; // "BM", then reserved bytes that are always zero
    return ImageKind::NotAnImage;
}

const char* imageKindName(ImageKind kind) {
    switch (kind) {
    case ImageKind::NotAnImage:
        return "non-image";
    case ImageKind::Png:
        return "PNG";
    case ImageKind::Tiff:
        return "TIFF";
    case ImageKind::Jpeg:
        return "JPEG";
    case ImageKind::Gif:
        return "GIF";
    case ImageKind::Webp:
        return "WebP";
    case ImageKind::Exr:
        return "OpenEXR";
    case ImageKind::Bmp:
        return "BMP";
    }
    return "unknown";
}

std::string genomeXmpPacket(const std::string& genomeText) {
    std::string escaped;
    escaped.reserve(genomeText.size() + genomeText.size() / 16);
    for (char c : genomeText) {
        if (c == '&')
            escaped += "&amp;";
        else if (c == '<')
            escaped += "&lt;";
        else if (c == '>')
            escaped += "&gt;";
        else
            escaped += c;
    }
    return std::string("<?xpacket begin=\"\xEF\xBB\xBF\" id=\"W5M0MpCehiHzreSzNTczkc9d\"?>\n"
                       "<x:xmpmeta xmlns:x=\"adobe:ns:meta/\">\n"
                       " <rdf:RDF xmlns:rdf=\"http://www.w3.org/1999/02/22-rdf-syntax-ns#\">\n"
                       "  <rdf:Description rdf:about=\"\" xmlns:") +
           XmpPrefix + "=\"" + XmpNamespace + "\">\n   <" + XmpPrefix + ":" + XmpProperty + ">" + escaped +
           "</" + XmpPrefix + ":" + XmpProperty +
           ">\n  </rdf:Description>\n </rdf:RDF>\n</x:xmpmeta>\n<?xpacket end=\"w\"?>";
}

std::optional<std::string> genomeFromXmp(std::string_view xml) {
    for (const std::string& prefix : prefixesOf(xml)) {
        const std::string name = prefix + ":" + XmpProperty;
        for (std::size_t at = xml.find(name); at != std::string_view::npos; at = xml.find(name, at + 1)) {
            const std::size_t after = at + name.size();
            if (after >= xml.size() || at == 0 || isNameChar(xml[after])) continue;
            if (xml[at - 1] == '<') {
                // Element form: <marbler:genome>text</marbler:genome>.
                std::size_t open = xml.find('>', after);
                if (open == std::string_view::npos || xml[open - 1] == '/') continue;
                std::size_t close = xml.find("</" + name, open + 1);
                if (close == std::string_view::npos) continue;
                return decodeXmlText(xml.substr(open + 1, close - open - 1));
            }
            if (isXmlSpace(xml[at - 1])) {
                // Attribute form, as some tools write simple properties: marbler:genome="text".
                std::size_t eq = after;
                while (eq < xml.size() && isXmlSpace(xml[eq]))
                    ++eq;
                if (eq >= xml.size() || xml[eq] != '=') continue;
                std::size_t quote = eq + 1;
                while (quote < xml.size() && isXmlSpace(xml[quote]))
                    ++quote;
                if (quote >= xml.size() || (xml[quote] != '"' && xml[quote] != '\'')) continue;
                std::size_t close = xml.find(xml[quote], quote + 1);
                if (close == std::string_view::npos) continue;
                return decodeXmlText(xml.substr(quote + 1, close - quote - 1));
            }
        }
    }
    return std::nullopt;
}

std::optional<std::string> readGenomeText(const std::filesystem::path& file, ImageKind kind,
                                          const std::string& name) {
    FileSource source(file, name);
    return readFromSource(source, kind, name);
}

std::optional<std::string> readGenomeText(std::span<const unsigned char> bytes, ImageKind kind,
                                          const std::string& name) {
    MemorySource source(bytes);
    return readFromSource(source, kind, name);
}

Genome parseEmbeddedGenome(const std::string& text, ImageKind kind, const std::string& name,
                           std::vector<std::string>* warnings) {
    return parseGenome(text, name + ": genome in " + imageKindName(kind) + " metadata", warnings);
}

Genome loadDesign(const std::filesystem::path& file, std::vector<std::string>* warnings) {
    const std::string name = file.string();
    unsigned char head[16] = {};
    std::size_t got = 0;
    if (std::FILE* f = std::fopen(file.c_str(), "rb")) {
        got = std::fread(head, 1, sizeof head, f); // a folder reads nothing, and loadGenome says so
        std::fclose(f);
    }
    const ImageKind kind = imageKindOf(std::span<const unsigned char>(head, got));
    if (kind == ImageKind::NotAnImage) {
        const std::string extension = lowerExtension(file);
        const bool namedAsImage = extension == ".png" || extension == ".tif" || extension == ".tiff";
        try {
            return loadGenome(file, warnings);
        } catch (const GenomeError& e) {
            // A broken image is likelier than genome JSON under an image's name: say both.
            if (!namedAsImage || got == 0) throw;
            std::string detail = e.what();
            if (detail.starts_with(name + ": ")) detail.erase(0, name.size() + 2);
            throw InputError(name + " is not a " + (extension == ".png" ? "PNG" : "TIFF") +
                             " image (it does not start like one) nor a genome file (" + detail + ")");
        }
    }
    std::optional<std::string> text = readGenomeText(file, kind, name);
    if (!text) throw InputError(name + " is an image without a Marbler genome in it");
    Genome genome = parseEmbeddedGenome(*text, kind, name, warnings);
    // The same rule as for a genome file: a relative source lies beside the image.
    std::filesystem::path folder = file.parent_path();
    genome.baseDirectory = folder.empty() ? std::string(".") : folder.string();
    genome.fileName = name; // errors about its source name the image
    return genome;
}

} // namespace marbler
