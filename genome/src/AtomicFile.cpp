// Write to a temporary beside the target, flush, rename (marbler/AtomicFile.h).

#include "marbler/AtomicFile.h"

#include "marbler/Error.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace marbler {
namespace fs = std::filesystem;

std::string writeFailureMessage(const fs::path& file, int error, const std::string& reason) {
    if (error == ENOSPC || error == EDQUOT) {
        std::error_code ec;
        fs::path whole = fs::absolute(file, ec);
        if (ec) whole = file;
        const fs::path folder = whole.parent_path().empty() ? fs::path(".") : whole.parent_path();
        return "the disk is full: could not write " + whole.string() + " (free some space in " +
               folder.string() + " or choose another folder)";
    }
    return "cannot write " + file.string() + ": " + (reason.empty() ? std::strerror(error) : reason);
}

namespace {

[[noreturn]] void writeFailure(const fs::path& file, int error) {
    throw RuntimeFailure(writeFailureMessage(file, error));
}

fs::path folderOf(const fs::path& file) {
    fs::path folder = file.parent_path();
    return folder.empty() ? fs::path(".") : folder;
}

/// fsync of a file or folder by name; a failure is returned as errno (0: done).
int syncPath(const fs::path& path, bool folder) {
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | (folder ? O_DIRECTORY : 0));
    if (fd < 0) return errno;
    int error = ::fsync(fd) == 0 ? 0 : errno;
    ::close(fd);
    return error;
}

} // namespace

AtomicFile::AtomicFile(fs::path target, Kind kind)
    : mTarget(std::move(target))
    , mKind(kind) {
    static std::atomic<unsigned> counter{0};
    if (mTarget.filename().empty() || mTarget.filename() == "." || mTarget.filename() == "..")
        throw RuntimeFailure("cannot write " + mTarget.string() + ": not a file name");
    const fs::path folder = folderOf(mTarget);
    int error = EEXIST;
    for (int attempt = 0; attempt < 100 && error == EEXIST; ++attempt) {
        mTemporary = folder / ("." + mTarget.stem().string() + ".part-" + std::to_string(::getpid()) + "-" +
                               std::to_string(counter.fetch_add(1)) + mTarget.extension().string());
        if (mKind == Kind::Folder) {
            error = ::mkdir(mTemporary.c_str(), 0777) == 0 ? 0 : errno;
        } else {
            int fd = ::open(mTemporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
            error = fd >= 0 ? 0 : errno;
            if (fd >= 0) ::close(fd);
        }
    }
    if (error != 0) writeFailure(mTarget, error);
}

AtomicFile::~AtomicFile() {
    if (!mCommitted) removeTemporary();
}

void AtomicFile::removeTemporary() noexcept {
    std::error_code ec;
    if (mKind == Kind::Folder)
        fs::remove_all(mTemporary, ec);
    else
        fs::remove(mTemporary, ec);
}

void AtomicFile::write(std::string_view bytes) {
    int fd = ::open(mTemporary.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    if (fd < 0) writeFailure(mTarget, errno);
    const char* data = bytes.data();
    std::size_t left = bytes.size();
    while (left > 0) {
        ssize_t written = ::write(fd, data, left);
        if (written < 0) {
            if (errno == EINTR) continue;
            int error = errno;
            ::close(fd);
            writeFailure(mTarget, error);
        }
        data += written;
        left -= static_cast<std::size_t>(written);
    }
    if (::close(fd) != 0) writeFailure(mTarget, errno);
}

void AtomicFile::commit() {
    if (mCommitted) return;
    // A folder's files are flushed by their writers; the folder itself is flushed with its parent.
    if (mKind == Kind::File) {
        if (int error = syncPath(mTemporary, false); error != 0) {
            removeTemporary();
            writeFailure(mTarget, error);
        }
    }
    if (::rename(mTemporary.c_str(), mTarget.c_str()) != 0) {
        int error = errno;
        removeTemporary();
        writeFailure(mTarget, error);
    }
    mCommitted = true;
    // Persist the rename itself; a failure here loses nothing already written, so it is ignored.
    syncPath(folderOf(mTarget), true);
}

AtomicFileSet::~AtomicFileSet() {
    if (mCommitted) return;
    std::error_code ec;
    for (const auto& file : mFiles)
        if (file->committed()) fs::remove(file->target(), ec);
}

AtomicFile& AtomicFileSet::add(const fs::path& target) {
    mFiles.push_back(std::make_unique<AtomicFile>(target));
    return *mFiles.back();
}

std::vector<fs::path> AtomicFileSet::commit() {
    std::vector<fs::path> written;
    for (const auto& file : mFiles) {
        file->commit();
        written.push_back(file->target());
    }
    mCommitted = true;
    return written;
}

void writeFileAtomically(const fs::path& file, std::string_view text) {
    AtomicFile out(file);
    out.write(text);
    out.commit();
}

} // namespace marbler
