// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "output_file.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <new>
#include <set>
#include <stdexcept>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace meff::cli
{

namespace fs = std::filesystem;

namespace
{

std::runtime_error WriteError(const std::string& path, const std::string& reason)
{
    return std::runtime_error("cannot write " + path + ": " + reason);
}

std::runtime_error WriteError(const std::string& path, int error)
{
    return WriteError(path, std::strerror(error));
}

// ---------------------------------------------------------------------------------------------
// Temporary files the signal handler removes. A fixed table of pointers, because a signal
// handler may neither allocate nor take a lock; lock-free atomics are async-signal-safe.

constexpr int kTemporarySlots = 64;
std::atomic<const char*> g_temporaries[kTemporarySlots];
static_assert(std::atomic<const char*>::is_always_lock_free);

/// The signals that end the process by default and may come in the middle of a write, each
/// with the line said on stderr (fixed text: a handler may not format). SIGXFSZ is not among
/// them: it is ignored, so that a write past the file-size limit fails with EFBIG and is said
/// like any other write error (exit status 1).
struct CleanupSignal
{
    int signal;
    const char* line;
};
constexpr CleanupSignal kCleanupSignals[] = {
    {SIGINT, "meff: interrupted (SIGINT); unfinished output files removed\n"},
    {SIGTERM, "meff: terminated (SIGTERM); unfinished output files removed\n"},
    {SIGHUP, "meff: hung up (SIGHUP); unfinished output files removed\n"},
    {SIGQUIT, "meff: quit (SIGQUIT); unfinished output files removed\n"},
    {SIGXCPU, "meff: CPU time limit exceeded (SIGXCPU); unfinished output files removed\n"},
    {SIGALRM, "meff: alarm (SIGALRM); unfinished output files removed\n"},
    {SIGUSR1, "meff: SIGUSR1; unfinished output files removed\n"},
    {SIGUSR2, "meff: SIGUSR2; unfinished output files removed\n"},
};

/// Async-signal-safe: unlink and atomic loads only.
void RemoveTemporaries()
{
    for (std::atomic<const char*>& slot : g_temporaries)
    {
        if (const char* path = slot.load())
        {
            ::unlink(path);
        }
    }
}

extern "C" void RemoveTemporariesAndDie(int signal)
{
    const int savedErrno = errno;
    RemoveTemporaries();
    for (const CleanupSignal& cleanup : kCleanupSignals)
    {
        if (cleanup.signal == signal)
        {
            // A progress line may be open on a terminal: start on a line of our own.
            const char* line = cleanup.line;
            [[maybe_unused]] const ssize_t written =
                ::write(STDERR_FILENO, line, std::strlen(line));
        }
    }
    errno = savedErrno;
    // SA_RESETHAND restored the default action: end the process as the signal would have (the
    // shell then sees 128 + signal, and a Ctrl-C stops a script that ran meff).
    ::raise(signal);
}

// ---------------------------------------------------------------------------------------------
// Temporary files' names. ".NAME.meff-HOST-PID.XXXXXX" beside NAME: hidden, recognisably meff's,
// and saying which process wrote it, so that one left by a process that can no longer remove
// it (kill -9, a crash, a power cut) is removed by the next run writing into that folder, and
// only then: never the file of a live run, nor of another machine sharing the folder.

/// ".meff-HOST-" of this machine.
const std::string& TemporaryMark()
{
    static const std::string mark = []
    {
        char host[256] = {};
        if (::gethostname(host, sizeof host - 1) != 0)
        {
            host[0] = '\0';
        }
        return ".meff-" + std::string(host) + "-";
    }();
    return mark;
}

std::string TemporaryTemplate(const fs::path& destination)
{
    return (destination.parent_path() / ("." + destination.filename().string() + TemporaryMark() +
                                         std::to_string(::getpid()) + ".XXXXXX"))
        .string();
}

/// The process that wrote temporary file `name` of this machine, or -1 when `name` is not one.
pid_t WriterOf(const std::string& name)
{
    const std::size_t mark = name.rfind(TemporaryMark());
    if (name.empty() || name[0] != '.' || mark == std::string::npos)
    {
        return -1;
    }
    const std::size_t digits = mark + TemporaryMark().size();
    const std::size_t dot = name.find('.', digits);
    if (dot == std::string::npos || dot == digits || dot - digits > 9 || name.size() != dot + 7 ||
        name.find_first_not_of("0123456789", digits) != dot)
    {
        return -1;
    }
    return pid_t(std::stol(name.substr(digits, dot - digits)));
}

/// Removes, once per folder and process, the temporary files that processes of this machine
/// which no longer run left in `folder`.
void RemoveStaleTemporaries(const fs::path& folder)
{
    static std::mutex mutex;
    static std::set<std::string> cleaned;
    const std::lock_guard lock(mutex);
    if (!cleaned.insert(folder.string()).second)
    {
        return;
    }
    std::error_code error;
    for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error))
    {
        const pid_t writer = WriterOf(it->path().filename().string());
        if (writer > 0 && writer != ::getpid() && ::kill(writer, 0) != 0 && errno == ESRCH)
        {
            ::unlink(it->path().c_str());
        }
    }
}

/// Blocks the cleanup signals while a temporary file is created and registered, so that no
/// signal can come between the two and leave the file behind.
class CleanupSignalsBlocked
{
  public:
    CleanupSignalsBlocked()
    {
        sigset_t set;
        sigemptyset(&set);
        for (const CleanupSignal& cleanup : kCleanupSignals)
        {
            sigaddset(&set, cleanup.signal);
        }
        ::sigprocmask(SIG_BLOCK, &set, &m_previous);
    }
    ~CleanupSignalsBlocked() { ::sigprocmask(SIG_SETMASK, &m_previous, nullptr); }
    CleanupSignalsBlocked(const CleanupSignalsBlocked&) = delete;
    CleanupSignalsBlocked& operator=(const CleanupSignalsBlocked&) = delete;

  private:
    sigset_t m_previous;
};

// ---------------------------------------------------------------------------------------------
// Where an output goes.

/// How an output path is written.
struct Destination
{
    bool writeThrough = false;
    int descriptor = -1;  ///< write through this already open descriptor (dup'ed), or -1
    std::string path;     ///< whole-or-nothing: the regular file to replace (links followed)
    bool exists = false;  ///< whole-or-nothing: the file exists (keep its permissions)
    mode_t mode = 0;      ///< its permissions
    std::string identity; ///< the same for two paths that reach the same file
};

constexpr int kMaxSymbolicLinks = 40; // as Linux's own limit on a path's links

/// The process's umask, for the permissions of a new file. umask() can only be read by setting
/// it (umask(0), then umask(mask) back), so two threads reading it at once could leave it at 0
/// and files world-writable (issue 36: `render --jobs 64` left 208 of 3,000 frames at 0666).
/// It is read once, here, during the static initialisation of the program, before main()
/// and so before any thread exists; nothing in meff changes it afterwards.
const mode_t g_umask = []
{
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return mask;
}();

/// An open file of this process named through /proc (/dev/stdout is a link to
/// /proc/self/fd/1): its descriptor, or -1.
int OwnDescriptor(const fs::path& directory, const fs::path& name)
{
    const std::string self = "/proc/" + std::to_string(::getpid()) + "/fd";
    const std::string text = name.string();
    if (directory != self || text.empty() ||
        text.find_first_not_of("0123456789") != std::string::npos || text.size() > 9)
    {
        return -1;
    }
    return std::stoi(text);
}

std::string FileIdentity(const struct stat& status)
{
    return "inode " + std::to_string(status.st_dev) + ":" + std::to_string(status.st_ino);
}

/// The identity of whatever standard output is, or empty.
std::string StandardOutputIdentity()
{
    struct stat status;
    return ::fstat(STDOUT_FILENO, &status) == 0 ? FileIdentity(status) : std::string();
}

Destination Follow(const std::string& path);

/// Follows `path` through its symbolic links to what it names. Throws WriteError for a
/// directory that cannot be reached, a loop of links, or a path naming a directory.
Destination Resolve(const std::string& path)
{
    Destination destination = Follow(path);
    if (!destination.identity.empty() && destination.identity == StandardOutputIdentity())
    {
        destination.identity = "standard output";
    }
    return destination;
}

Destination Follow(const std::string& path)
{
    Destination destination;
    if (path == "-")
    {
        destination.writeThrough = true;
        destination.descriptor = STDOUT_FILENO;
        destination.identity = "standard output";
        return destination;
    }
    fs::path current(path);
    for (int links = 0; links <= kMaxSymbolicLinks; ++links)
    {
        if (current.filename().empty() || current.filename() == "." || current.filename() == "..")
        {
            throw WriteError(path, "is a directory");
        }
        std::error_code error;
        const fs::path parent = current.has_parent_path() ? current.parent_path() : fs::path(".");
        const fs::path directory = fs::canonical(parent, error);
        if (error)
        {
            throw WriteError(path, error.message());
        }
        const fs::path here = directory / current.filename();
        // /proc's links name open files (pipes, terminals, deleted files), not paths: write to
        // the open file itself.
        if (directory.string().rfind("/proc/", 0) == 0)
        {
            destination.writeThrough = true;
            destination.descriptor = OwnDescriptor(directory, current.filename());
            struct stat status;
            destination.identity =
                ::stat(here.c_str(), &status) == 0 ? FileIdentity(status) : here.string();
            return destination;
        }
        struct stat status;
        if (::lstat(here.c_str(), &status) != 0)
        {
            if (errno != ENOENT)
            {
                throw WriteError(path, errno);
            }
            destination.path = here.string(); // a new file
            destination.identity = destination.path;
            return destination;
        }
        if (S_ISLNK(status.st_mode))
        {
            const fs::path target = fs::read_symlink(here, error);
            if (error)
            {
                throw WriteError(path, error.message());
            }
            current = target.is_absolute() ? target : directory / target;
            continue;
        }
        if (S_ISDIR(status.st_mode))
        {
            throw WriteError(path, "is a directory");
        }
        destination.identity = FileIdentity(status);
        if (S_ISREG(status.st_mode))
        {
            destination.path = here.string();
            destination.exists = true;
            destination.mode = status.st_mode & 07777;
            return destination;
        }
        // A device, a FIFO or a socket: written in place, through the path as given.
        destination.writeThrough = true;
        return destination;
    }
    throw WriteError(path, std::strerror(ELOOP));
}

} // namespace

OutputFile::OutputFile(std::string path) : m_path(std::move(path))
{
    const Destination destination = Resolve(m_path);
    m_toStandardOutput = destination.identity == "standard output";
    m_writeThrough = destination.writeThrough;
    if (m_writeThrough)
    {
        if (destination.descriptor == STDOUT_FILENO && m_path == "-")
        {
            m_stream = stdout;
            m_ownsStream = false;
            return;
        }
        // Opened without O_CREAT or O_TRUNC: a device or pipe has nothing to truncate, and an
        // open file of ours (/dev/stdout redirected to a file, perhaps for appending) is
        // written through its own descriptor, at its own offset.
        const int descriptor = destination.descriptor >= 0
                                   ? ::fcntl(destination.descriptor, F_DUPFD_CLOEXEC, 0)
                                   : ::open(m_path.c_str(), O_WRONLY | O_CLOEXEC);
        if (descriptor < 0)
        {
            throw WriteError(m_path, errno);
        }
        m_stream = ::fdopen(descriptor, "w");
        if (m_stream == nullptr)
        {
            const int error = errno;
            ::close(descriptor);
            throw WriteError(m_path, error);
        }
        return;
    }

    m_destination = destination.path;
    const fs::path target(m_destination);
    RemoveStaleTemporaries(target.parent_path());
    // Same directory as the destination, so that the final rename is atomic.
    std::string temporary = TemporaryTemplate(target);
    int descriptor = -1;
    {
        const CleanupSignalsBlocked blocked;
        descriptor = ::mkstemp(temporary.data());
        if (descriptor < 0)
        {
            throw WriteError(m_path, errno);
        }
        m_temporaryPath = std::move(temporary);
        m_registration = RegisterTemporary(m_temporaryPath);
    }
    // mkstemp makes the file private (0600): give it the permissions of the file it replaces,
    // or those a new file would get.
    mode_t mode = destination.mode;
    if (!destination.exists)
    {
        mode = 0666 & ~g_umask;
    }
    ::fchmod(descriptor, mode);
    m_stream = ::fdopen(descriptor, "w");
    if (m_stream == nullptr)
    {
        const int error = errno;
        ::close(descriptor);
        Discard();
        throw WriteError(m_path, error);
    }
}

OutputFile::~OutputFile()
{
    Discard();
}

void OutputFile::CheckWrites()
{
    // ferror does not keep the reason: errno still has it, from the write that failed (the
    // caller clears errno before writing).
    const int error = errno;
    if (m_stream != nullptr && std::ferror(m_stream) != 0)
    {
        throw WriteError(m_path, error != 0 ? error : EIO);
    }
}

void OutputFile::Commit()
{
    const bool writeFailed = std::ferror(m_stream) != 0;
    int closeResult = std::fflush(m_stream);
    // Whole or not at all after a crash of the machine too: the data is on the disk before the
    // rename makes it the file (and the rename itself, by the folder's fsync below).
    if (closeResult == 0 && !m_writeThrough && ::fsync(::fileno(m_stream)) != 0)
    {
        closeResult = -1;
    }
    int error = errno;
    if (m_ownsStream && std::fclose(m_stream) != 0 && closeResult == 0)
    {
        closeResult = -1;
        error = errno;
    }
    m_stream = nullptr;
    if (writeFailed || closeResult != 0)
    {
        Discard();
        throw WriteError(m_path, writeFailed && closeResult == 0 ? EIO : error);
    }
    if (WritesThrough())
    {
        return;
    }
    if (std::rename(m_temporaryPath.c_str(), m_destination.c_str()) != 0)
    {
        const int renameError = errno;
        Discard();
        throw WriteError(m_path, renameError);
    }
    // The rename made durable. A folder that cannot be synced (some file systems refuse it)
    // still has the whole file: the rename is done either way.
    if (const int folder = ::open(fs::path(m_destination).parent_path().c_str(),
                                  O_RDONLY | O_DIRECTORY | O_CLOEXEC);
        folder >= 0)
    {
        ::fsync(folder);
        ::close(folder);
    }
    UnregisterTemporary(m_registration);
    m_registration = -1;
    m_temporaryPath.clear();
}

void OutputFile::Discard()
{
    if (m_stream != nullptr)
    {
        if (m_ownsStream)
        {
            std::fclose(m_stream);
        }
        else
        {
            std::fflush(m_stream);
        }
        m_stream = nullptr;
    }
    if (!m_temporaryPath.empty())
    {
        std::remove(m_temporaryPath.c_str());
        UnregisterTemporary(m_registration);
        m_registration = -1;
        m_temporaryPath.clear();
    }
}

bool SameOutput(const std::string& a, const std::string& b)
{
    try
    {
        return Resolve(a).identity == Resolve(b).identity;
    }
    catch (const std::exception&)
    {
        return a == b; // said when the output is opened
    }
}

void RemoveTemporariesOnSignal()
{
    struct sigaction action;
    std::memset(&action, 0, sizeof action);
    action.sa_handler = RemoveTemporariesAndDie;
    action.sa_flags = SA_RESETHAND;
    sigemptyset(&action.sa_mask);
    for (const CleanupSignal& cleanup : kCleanupSignals)
    {
        sigaddset(&action.sa_mask, cleanup.signal);
    }
    for (const CleanupSignal& cleanup : kCleanupSignals)
    {
        struct sigaction previous;
        // A signal ignored by whoever started us (nohup) stays ignored.
        if (::sigaction(cleanup.signal, nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN)
        {
            continue;
        }
        ::sigaction(cleanup.signal, &action, nullptr);
    }
    std::signal(SIGPIPE, SIG_IGN);
    // A write past the file-size limit (ulimit -f) then fails with EFBIG, said in words, instead
    // of the signal killing the process with nothing said and the temporary file left.
    std::signal(SIGXFSZ, SIG_IGN);
}

void EndOnOutOfMemory()
{
    std::set_new_handler(
        []
        {
            // Called where an allocation failed: perhaps in a destructor or a noexcept
            // function, where a std::bad_alloc would abort. Nothing here allocates.
            RemoveTemporaries();
            constexpr char kLine[] = "meff: out of memory\n";
            [[maybe_unused]] const ssize_t written =
                ::write(STDERR_FILENO, kLine, sizeof kLine - 1);
            ::_exit(1);
        });
}

int RegisterTemporary(const std::string& path)
{
    for (int slot = 0; slot < kTemporarySlots; ++slot)
    {
        const char* expected = nullptr;
        if (g_temporaries[slot].compare_exchange_strong(expected, path.c_str()))
        {
            return slot;
        }
    }
    return -1;
}

void UnregisterTemporary(int slot)
{
    if (slot >= 0 && slot < kTemporarySlots)
    {
        g_temporaries[slot].store(nullptr);
    }
}

} // namespace meff::cli
