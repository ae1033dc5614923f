#include "marbler/gl/ShaderSource.h"

#include "marbler/Error.h"

#include <QFile>

#include <set>
#include <sstream>
#include <vector>

// Resources of a static library are not registered until something asks for them.
static void initShaderResources() {
    Q_INIT_RESOURCE(marbler_shaders);
}

namespace marbler::gl {
namespace {

std::string expand(const std::string& source, const std::function<std::string(const std::string&)>& load,
                   std::vector<std::string>& stack, std::set<std::string>& done) {
    std::istringstream in(source);
    std::string out;
    std::string line;
    while (std::getline(in, line)) {
        std::size_t first = line.find_first_not_of(" \t");
        if (first != std::string::npos && line.compare(first, 8, "#include") == 0) {
            std::size_t open = line.find('"', first + 8);
            std::size_t close = open == std::string::npos ? open : line.find('"', open + 1);
            if (close == std::string::npos) throw RuntimeFailure("GLSL: malformed #include line: " + line);
            std::string name = line.substr(open + 1, close - open - 1);
            for (const std::string& open : stack)
                if (open == name) throw RuntimeFailure("GLSL: #include cycle through \"" + name + "\"");
            if (done.insert(name).second) {
                stack.push_back(name);
                out += expand(load(name), load, stack, done);
                stack.pop_back();
            }
            continue;
        }
        out += line;
        out += '\n';
    }
    return out;
}

} // namespace

std::string shaderFile(const std::string& name) {
    initShaderResources();
    QFile file(QStringLiteral(":/marbler/shaders/") + QString::fromStdString(name));
    if (!file.open(QIODevice::ReadOnly))
        throw RuntimeFailure("GLSL: no shader file \"" + name + "\" in the library");
    QByteArray bytes = file.readAll();
    return std::string(bytes.constData(), std::size_t(bytes.size()));
}

std::string expandIncludes(const std::string& source,
                           const std::function<std::string(const std::string&)>& load) {
    std::vector<std::string> stack;
    std::set<std::string> done;
    return expand(source, load, stack, done);
}

std::string assembledShader(const std::string& name) {
    return expandIncludes(shaderFile(name), [](const std::string& n) { return shaderFile(n); });
}

std::string numberLines(const std::string& source) {
    std::istringstream in(source);
    std::ostringstream out;
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        out.width(5);
        out << number << "  " << line << '\n';
    }
    return out.str();
}

} // namespace marbler::gl
