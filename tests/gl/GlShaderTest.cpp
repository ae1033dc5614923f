// Shader plumbing: the shipped sources, include expansion, and compile errors that carry the
// assembled source and the driver's log.

#include "GlTestUtil.h"
#include "marbler/Error.h"
#include "marbler/gl/ShaderSource.h"

#include <gtest/gtest.h>

#include <map>

namespace marbler {
namespace {

TEST(ShaderSource, EveryShaderIncludesTheOneToolsFile) {
    std::string tools = gl::shaderFile("tools.glsl");
    ASSERT_NE(tools.find("int traceColor"), std::string::npos);
    for (const char* name : {"raster.frag", "mesh.frag"}) {
        std::string text = gl::assembledShader(name);
        EXPECT_EQ(text.find("#include"), std::string::npos) << name;
        EXPECT_NE(text.find("int traceColor"), std::string::npos) << name;
    }
}

TEST(ShaderSource, IncludesExpandOnceAndCyclesThrow) {
    std::map<std::string, std::string> files = {
        {"a", "A\n#include \"b\"\n"}, {"b", "B\n"}, {"c", "#include \"c\"\n"}};
    auto load = [&](const std::string& n) { return files.at(n); };
    EXPECT_EQ(gl::expandIncludes("#include \"a\"\n#include \"b\"\nmain\n", load), "A\nB\nmain\n");
    EXPECT_THROW(gl::expandIncludes("#include \"c\"\n", load), RuntimeFailure);
    EXPECT_THROW(gl::shaderFile("no-such.glsl"), RuntimeFailure);
    EXPECT_EQ(gl::numberLines("x\ny\n"), "    1  x\n    2  y\n");
}

TEST(ShaderCompile, ErrorsCarryTheNumberedSourceAndTheLog) {
    MARBLER_REQUIRE_GL_OR_SKIP();
    std::string vertex = gl::shaderFile("fullscreen.vert");
    std::string broken = "#version 430 core\n#include \"tools.glsl\"\nout vec4 colour;\n"
                         "void main() { colour = vec4(undefinedThing); }\n";
    try {
        test::glRenderer()->checkProgram(vertex, broken);
        FAIL() << "a broken shader compiled";
    } catch (const RuntimeFailure& e) {
        std::string what = e.what();
        EXPECT_NE(what.find("fragment"), std::string::npos) << what.substr(0, 400);
        EXPECT_NE(what.find("undefinedThing"), std::string::npos) << what.substr(0, 400);
        EXPECT_NE(what.find("    1  #version 430 core"), std::string::npos);
        EXPECT_NE(what.find("int traceColor"), std::string::npos) << "the included source is quoted";
    }
    // The shipped programs compile through the same helper.
    EXPECT_NO_THROW(test::glRenderer()->checkProgram(vertex, gl::shaderFile("raster.frag")));
}

} // namespace
} // namespace marbler
