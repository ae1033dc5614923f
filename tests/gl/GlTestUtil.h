#pragma once
/// Shared by the GL tests: the one renderer of the process, the skip-or-fail rule, images.

#include "marbler/Sampling.h"
#include "marbler/gl/GlRenderer.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace marbler::test {

/// The process's renderer, made on first use; nullptr when GL is not available.
gl::GlRenderer* glRenderer();

/// Whether MARBLER_REQUIRE_GL=1 asks for GL tests to fail rather than skip.
bool glRequired();

/// Saves an 8-bit RGB image as PNG (for failures and baselines).
void savePng(const Image& image, const std::filesystem::path& file);
/// Reads a PNG as 8-bit RGB; an empty image when the file is missing.
Image loadPng(const std::filesystem::path& file);

} // namespace marbler::test

/// Skips the test (with the reason) when no GL context can be made, or fails it when
/// MARBLER_REQUIRE_GL=1 (CI, where the GL tests must really run).
#define MARBLER_REQUIRE_GL_OR_SKIP()                                                                         \
    do {                                                                                                     \
        std::string glWhy;                                                                                   \
        if (!::marbler::gl::GlRenderer::available(&glWhy)) {                                                 \
            if (::marbler::test::glRequired()) FAIL() << "MARBLER_REQUIRE_GL=1 but no GL: " << glWhy;        \
            GTEST_SKIP() << "no OpenGL context: " << glWhy;                                                  \
        }                                                                                                    \
    } while (false)
