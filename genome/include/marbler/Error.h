#pragma once
/// The one exception hierarchy of Marbler. Every library function that can fail throws a
/// subclass of marbler::Error; the edges (the command line, the window) catch it and report.

#include <stdexcept>
#include <string>

namespace marbler {

/// Base of every error Marbler throws on purpose.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Bad input from the user: a broken genome file, an image that will not load, an absurd size,
/// a wrong command-line option. The command line exits with status 2 for these.
class InputError : public Error {
public:
    using Error::Error;
};

/// A genome file or genome text that breaks the format. The message names the file and the
/// JSON location, e.g. `a.marble.json: operations[3].radius: must be > 0 (got -2)`.
class GenomeError : public InputError {
public:
    GenomeError(const std::string& file, const std::string& location, const std::string& what)
        : InputError(file + ": " + (location.empty() ? "" : location + ": ") + what)
        , mFile(file)
        , mLocation(location) {}
    const std::string& file() const { return mFile; }
    const std::string& location() const { return mLocation; }

private:
    std::string mFile;
    std::string mLocation;
};

/// A failure that is not the user's input: I/O, out of memory, a GL driver error.
class RuntimeFailure : public Error {
public:
    using Error::Error;
};

/// Work stopped because the caller asked it to (a cancel button, a closed window).
class Cancelled : public Error {
public:
    Cancelled()
        : Error("cancelled") {}
};

} // namespace marbler
