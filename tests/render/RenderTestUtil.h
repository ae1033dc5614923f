#pragma once
/// Helpers of the render tests: genomes from the conformance files, images read back.

#include "marbler/Genome.h"
#include "marbler/Sampling.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace marbler::test {

/// A conformance file (tests/data/conformance/NAME) as JSON.
nlohmann::json loadConformance(const std::string& name);

/// The genome embedded in a conformance file.
Genome genomeOf(const nlohmann::json& file, const std::string& name);

/// Reads an image file back as 8-bit RGB (through OpenImageIO). Fails the test when it cannot.
Image readImage8(const std::filesystem::path& file);

/// The largest channel difference between two images of equal size, and the share of pixels
/// whose channels all differ by at most `tolerance`.
struct ImageDiff {
    int maxDifference = 0;
    double shareWithin = 0.0;
};
ImageDiff compareImages(const Image& a, const Image& b, int tolerance);

} // namespace marbler::test
