#include "TestUtil.h"

#include "marbler/GenomeIO.h"
#include "marbler/Params.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace marbler::test {

std::filesystem::path dataDir() {
    return MARBLER_TEST_DATA;
}

std::filesystem::path outputDir(const std::string& name) {
    std::filesystem::path dir = std::filesystem::path(MARBLER_TEST_OUTPUT) / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

std::string examplePath(const std::string& name) {
    return (dataDir() / "examples" / name).string();
}

Genome loadExample(const std::string& name) {
    return loadGenome(dataDir() / "examples" / name);
}

std::size_t lineCount(const std::string& text) {
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

std::string readFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + file.string());
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void writeFile(const std::filesystem::path& file, const std::string& text) {
    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
    std::ofstream out(file, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + file.string());
}

RunResult runMarbler(const std::vector<std::string>& args) {
    return runMarbler(args, {});
}

RunResult runMarbler(const std::vector<std::string>& args, const std::vector<EnvChange>& env) {
    // Capture through files rather than pipes: no risk of a full pipe blocking the child.
    static int counter = 0;
    std::filesystem::path dir = std::filesystem::path(MARBLER_TEST_OUTPUT) / "run";
    std::filesystem::create_directories(dir);
    std::string stem = (dir / (std::to_string(::getpid()) + "-" + std::to_string(counter++))).string();
    std::string outPath = stem + ".out", errPath = stem + ".err";

    pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        int out = ::open(outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        int err = ::open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ::dup2(out, 1);
        ::dup2(err, 2);
        for (const auto& [name, value] : env) {
            if (value)
                ::setenv(name.c_str(), value->c_str(), 1);
            else
                ::unsetenv(name.c_str());
        }
        std::vector<char*> argv;
        std::string exe = MARBLER_EXECUTABLE;
        argv.push_back(exe.data());
        std::vector<std::string> copy = args;
        for (std::string& a : copy)
            argv.push_back(a.data());
        argv.push_back(nullptr);
        ::execv(exe.c_str(), argv.data());
        ::_exit(127);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    RunResult result;
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    result.out = readFile(outPath);
    result.err = readFile(errPath);
    std::filesystem::remove(outPath);
    std::filesystem::remove(errPath);
    return result;
}

void addToolsUsed(const Genome& genome, std::set<std::string>& seen) {
    const int dimension = genome.dimension;
    for (const std::vector<Operation>* list : {&genome.initial, &genome.operations}) {
        for (const Operation& op : *list) {
            const ToolSpec& spec = toolSpec(op.tool);
            const std::string tool = std::to_string(dimension) + "D " + std::string(spec.name);
            seen.insert(tool);
            for (const ParamSpec& param : spec.params(dimension))
                if (!param.choices.empty())
                    seen.insert(tool + " " + std::string(param.key) + "=" +
                                std::string(param.choices[std::size_t(getComponent(param, op, 0))]));
        }
    }
}

void expectEveryRegistryTool(const std::set<std::string>& seen, const std::string& what) {
    for (int dimension : {2, 3}) {
        for (const ToolSpec& spec : allTools()) {
            if (!spec.available(dimension)) continue;
            const std::string tool = std::to_string(dimension) + "D " + std::string(spec.name);
            EXPECT_TRUE(seen.count(tool)) << what << " " << tool;
            for (const ParamSpec& param : spec.params(dimension))
                for (std::string_view choice : param.choices) {
                    const std::string chosen =
                        tool + " " + std::string(param.key) + "=" + std::string(choice);
                    EXPECT_TRUE(seen.count(chosen)) << what << " " << chosen;
                }
        }
    }
}

} // namespace marbler::test
