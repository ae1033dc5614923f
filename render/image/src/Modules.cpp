#include "marbler/Modules.h"

#include "marbler/Error.h"

#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>
#include <system_error>
#include <vector>

#include <dlfcn.h>
#include <link.h>

namespace marbler {
namespace fs = std::filesystem;

namespace {

std::vector<fs::path> searchFolders() {
    std::vector<fs::path> folders;
    if (const char* dir = std::getenv("MARBLER_MODULE_DIR"); dir && *dir) folders.emplace_back(dir);
    std::error_code ec;
    fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        folders.push_back(self.parent_path());
        folders.push_back(self.parent_path().parent_path() / "lib" / "marbler");
    }
#ifdef MARBLER_BUILD_MODULE_DIR
    folders.emplace_back(MARBLER_BUILD_MODULE_DIR);
#endif
    return folders;
}

fs::path findModule(const std::string& fileName, std::string* searched) {
    for (const fs::path& folder : searchFolders()) {
        std::error_code ec;
        fs::path candidate = folder / fileName;
        if (fs::is_regular_file(candidate, ec)) return candidate;
        if (searched) *searched += (searched->empty() ? "" : ", ") + folder.string();
    }
    return {};
}

} // namespace

void* moduleEntry(const std::string& fileName, const std::string& entryName) {
    static std::mutex mutex;
    static std::map<std::string, void*> handles; // never closed: modules live as long as the process
    std::lock_guard lock(mutex);
    void*& handle = handles[fileName];
    if (!handle) {
        std::string searched;
        fs::path file = findModule(fileName, &searched);
        if (file.empty())
            throw RuntimeFailure("Marbler's module " + fileName + " is not installed (looked in " + searched +
                                 "; set MARBLER_MODULE_DIR to its folder)");
        handle = ::dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* why = ::dlerror();
            throw RuntimeFailure("cannot load " + file.string() + ": " + (why ? why : "unknown error"));
        }
    }
    void* entry = ::dlsym(handle, entryName.c_str());
    if (!entry)
        throw RuntimeFailure(fileName + " has no entry point " + entryName +
                             " (a module of another version?)");
    return entry;
}

bool moduleLoaded(const std::string& fileName) {
    // The process's list of loaded objects, not this copy's handle table: the window module
    // has its own copy of this code, which did not see the executable load the module.
    struct Search {
        const std::string* name;
        bool found = false;
    } search{&fileName};
    ::dl_iterate_phdr(
        [](dl_phdr_info* info, std::size_t, void* data) {
            auto* s = static_cast<Search*>(data);
            if (info->dlpi_name && fs::path(info->dlpi_name).filename() == *s->name) s->found = true;
            return s->found ? 1 : 0;
        },
        &search);
    return search.found;
}

std::string moduleLocation(const std::string& fileName) {
    std::string searched;
    fs::path file = findModule(fileName, &searched);
    return file.empty() ? "not found (looked in " + searched + ")" : file.string();
}

} // namespace marbler
