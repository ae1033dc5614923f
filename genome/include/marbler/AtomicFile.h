// Atomic writes: every file the program writes appears whole or not at all.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace marbler {

/// The message of a failed write of `file`: "cannot write FILE: REASON", where REASON is
/// strerror(error), or `reason` when given (a library's words); a full disk (ENOSPC, or a used-up
/// quota, EDQUOT) is said in plain words with the folder to free space in (issue 29: "Write
/// Error" and "TIFFAppendToStrip: Write error at scanline 3008" said neither). The one home of
/// that wording for every writer.
std::string writeFailureMessage(const std::filesystem::path& file, int error, const std::string& reason = {});

/// A file (or folder) written under a hidden temporary name beside its target and renamed over
/// the target by commit(), after its contents are flushed to disk. The temporary lives in the
/// target's folder so that the rename stays within one file system and is atomic. Destroyed
/// uncommitted (an exception, a cancel), it removes the temporary, so a failure never leaves a
/// half-written file or a stray temporary. The one home of write-then-rename.
class AtomicFile {
public:
    enum class Kind { File, Folder };

    /// Reserves a temporary beside `target`, creating it empty (a file, or a folder for
    /// Kind::Folder) so no other writer takes the name. The name is hidden and unique to this
    /// process and call, and keeps the target's extension, so writers that choose a format by
    /// extension see the right one. Throws RuntimeFailure naming the target.
    explicit AtomicFile(std::filesystem::path target, Kind kind = Kind::File);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    const std::filesystem::path& target() const { return mTarget; }
    /// Where to write until commit().
    const std::filesystem::path& temporary() const { return mTemporary; }
    bool committed() const { return mCommitted; }

    /// Writes `bytes` to the temporary file, replacing what it held. Throws RuntimeFailure.
    void write(std::string_view bytes);

    /// Flushes the temporary file to disk, renames it over the target (a folder replaces only an
    /// empty folder) and flushes the folder holding it. Throws RuntimeFailure naming the target;
    /// the temporary is then removed.
    void commit();

private:
    void removeTemporary() noexcept;

    std::filesystem::path mTarget, mTemporary;
    Kind mKind;
    bool mCommitted = false;
};

/// Several files committed together: renamed in the order added (so the last, the file the user
/// named, appears only when its companions are in place). Destroyed uncommitted, or when one
/// rename fails, it removes every file it wrote, renamed or not.
class AtomicFileSet {
public:
    AtomicFileSet() = default;
    ~AtomicFileSet();
    AtomicFileSet(const AtomicFileSet&) = delete;
    AtomicFileSet& operator=(const AtomicFileSet&) = delete;

    /// A new member; write to its temporary(). Throws RuntimeFailure.
    AtomicFile& add(const std::filesystem::path& target);

    /// Commits every member; returns the targets written. Throws RuntimeFailure.
    std::vector<std::filesystem::path> commit();

private:
    std::vector<std::unique_ptr<AtomicFile>> mFiles;
    bool mCommitted = false;
};

/// Writes text to a file atomically (an AtomicFile). Throws RuntimeFailure.
void writeFileAtomically(const std::filesystem::path& file, std::string_view text);

} // namespace marbler
