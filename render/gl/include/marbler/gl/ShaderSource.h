#pragma once
/// GLSL sources of the GL back end: the files of shaders/, shipped inside the library as Qt
/// resources, and the `#include "file"` expansion that lets the 2D, slice and mesh shaders share
/// one copy of the tool functions (tools.glsl).

#include <functional>
#include <string>

namespace marbler::gl {

/// The text of a shader file of shaders/ (e.g. "tools.glsl") as shipped. Throws RuntimeFailure
/// when the library holds no such file.
std::string shaderFile(const std::string& name);

/// Expands `#include "name"` lines (recursively; a file includes at most once per source, and a
/// cycle throws RuntimeFailure). `load` provides the text of a named file.
std::string expandIncludes(const std::string& source,
                           const std::function<std::string(const std::string&)>& load);

/// A shipped shader with its includes expanded.
std::string assembledShader(const std::string& name);

/// The source with 1-based line numbers, as error messages quote it (the driver's log counts
/// lines of the assembled source, since no #line directives are inserted).
std::string numberLines(const std::string& source);

} // namespace marbler::gl
