#pragma once
/// Genomes that travel inside images (spec/cli.md). Every PNG and TIFF Marbler writes carries
/// the canonical genome JSON of its design (serializeGenome) in its metadata:
///
/// - PNG: an iTXt chunk with the keyword `marbler-genome` (UTF-8; zlib-compressed when the text
///   is longer than PngCompressAbove bytes), written before the image data.
/// - TIFF: the XMP packet (tag 700) of the first image, holding the property `marbler:genome`
///   in the namespace XmpNamespace. XMP is the place applications keep their own metadata, and
///   the one that image editors and metadata tools carry over when they save a file again.
///
/// Reading uses libpng and libtiff alone (no OpenImageIO, no Qt), so any verb can take an image
/// where it takes a genome file and still start in milliseconds. What is read is parsed by
/// parseGenome, the same parser as a genome file's, and checked by the same rules.

#include "marbler/Genome.h"

#include <cstddef>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace marbler {

/// The PNG text keyword and the XMP namespace and property the genome is stored under.
inline constexpr const char* PngGenomeKeyword = "marbler-genome";
inline constexpr const char* XmpNamespace = "http://marbler.invalid/ns/genome/1.0/";
inline constexpr const char* XmpPrefix = "marbler";
inline constexpr const char* XmpProperty = "genome";
/// Genome text longer than this is deflated in its PNG chunk; shorter text stays readable with
/// any tool that lists a PNG's text.
inline constexpr std::size_t PngCompressAbove = 1024;

/// What a file's first bytes say it is. Only PNG and TIFF carry genomes; the other image kinds
/// are told apart so that a JPEG given as a genome is refused as an image, not as broken JSON.
enum class ImageKind { NotAnImage, Png, Tiff, Jpeg, Gif, Webp, Exr, Bmp };

/// The kind of file by its first bytes (at least 12 are looked at when there are that many).
ImageKind imageKindOf(std::span<const unsigned char> head);

/// The kind's usual name, e.g. "PNG".
const char* imageKindName(ImageKind kind);

/// The XMP packet that holds a genome's text (what the TIFF writer stores in tag 700).
std::string genomeXmpPacket(const std::string& genomeText);

/// The genome text an XMP packet holds (element or attribute form, any prefix bound to
/// XmpNamespace, XML entities decoded); nullopt when it holds none.
std::optional<std::string> genomeFromXmp(std::string_view packet);

/// The genome text carried by a PNG or TIFF image, read from a file or from memory; nullopt
/// when the image is readable but carries none. `name` is how messages name the image.
/// Throws InputError when the image cannot be read (truncated, corrupt, a chunk or tag over
/// the size limit), naming it.
std::optional<std::string> readGenomeText(const std::filesystem::path& file, ImageKind kind,
                                          const std::string& name);
std::optional<std::string> readGenomeText(std::span<const unsigned char> bytes, ImageKind kind,
                                          const std::string& name);

/// Parses genome text read from an image: errors name the image and where the genome was,
/// e.g. `design.png: genome in PNG metadata: operations[3].radius: must be > 0 (got -2)`.
/// Throws GenomeError.
Genome parseEmbeddedGenome(const std::string& text, ImageKind kind, const std::string& name,
                           std::vector<std::string>* warnings = nullptr);

/// Loads a design from a genome file or from a PNG or TIFF image that carries one, told apart
/// by the file's first bytes; the one loader of the command line's verbs and of the window.
/// Genome::baseDirectory is the file's folder either way, so a relative `source` image is
/// found beside the genome file or the image. Throws GenomeError for a bad genome file or
/// embedded genome, InputError for an image without a genome in it ("design.png is an image
/// without a Marbler genome in it"), an image of another kind, or one that cannot be read.
Genome loadDesign(const std::filesystem::path& file, std::vector<std::string>* warnings = nullptr);

} // namespace marbler
