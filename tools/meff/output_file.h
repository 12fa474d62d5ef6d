// Output files: regular files appear whole or not at all; anything else is written through.
#pragma once

#include <cstdio>
#include <string>

namespace meff::cli
{

/// An output named on the command line.
///
/// A regular file (or a new one) is written to a hidden temporary file in its directory and
/// renamed over it on Commit(), so a reader never sees half a file and a failed or interrupted
/// run leaves no file behind: the temporary is removed if the object is destroyed uncommitted,
/// and by RemoveTemporariesOnSignal's handler if the process is interrupted. A symbolic link is
/// followed: its final target is replaced, the link itself kept.
///
/// Anything else is written through, in place, as it is: "-" (standard output), a character or
/// block device (/dev/null, /dev/full), a FIFO, and an open file reached through /proc or
/// /dev/fd (/dev/stdout, /dev/stderr). Renaming over those would replace the device or pipe
/// with a regular file.
///
/// Every failure — a directory that does not exist or may not be read, a loop of symbolic
/// links, a full disk, a closed pipe — throws std::runtime_error "cannot write PATH: REASON".
class OutputFile
{
  public:
    /// Opens the output (creates the temporary file); throws std::runtime_error saying why it
    /// cannot.
    explicit OutputFile(std::string path);
    ~OutputFile();
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    std::FILE* Stream() { return m_stream; }
    const std::string& Path() const { return m_path; }
    /// Whether the output is written in place (not whole-or-nothing).
    bool WritesThrough() const { return m_writeThrough; }
    /// Whether the output is this process's standard output ("-", /dev/stdout, ...): the
    /// tool's own messages then go to standard error.
    bool ToStandardOutput() const { return m_toStandardOutput; }

    /// Throws std::runtime_error if a write has failed so far (a closed pipe, a full device),
    /// so that a long run stops as soon as its output is lost. Clear errno before the writes
    /// it checks: the reason is read from it.
    void CheckWrites();

    /// Flushes and closes; a regular file is renamed into place. Throws std::runtime_error on
    /// any failure (the temporary is then removed and the destination left untouched).
    void Commit();

  private:
    void Discard();

    std::string m_path;
    std::string m_temporaryPath; ///< empty when writing through
    std::string m_destination;   ///< where the temporary is renamed to (symbolic links followed)
    std::FILE* m_stream = nullptr;
    bool m_ownsStream = true; ///< false for "-": standard output is flushed, never closed
    bool m_writeThrough = false;
    bool m_toStandardOutput = false;
    int m_registration = -1; ///< slot of m_temporaryPath in the signal handler's list
};

/// The same file, or the same place where a file will be: true when two output paths would
/// write to one file (through links, "." and "..", or both being standard output). Never
/// throws: a path that cannot be resolved is compared as written.
bool SameOutput(const std::string& a, const std::string& b);

/// Installs handlers for SIGINT, SIGTERM and SIGHUP that remove every temporary file of an
/// uncommitted OutputFile (and of RegisterTemporary) and then let the signal end the process as
/// it would have. Also ignores SIGPIPE, so that a closed pipe is a write error said in words.
void RemoveTemporariesOnSignal();

/// Registers another temporary path for removal by the signal handler (a file a child process
/// writes, say); returns the slot to pass to UnregisterTemporary, or -1 when the list is full.
/// `path` must stay alive and unchanged until unregistered.
int RegisterTemporary(const std::string& path);
void UnregisterTemporary(int slot);

} // namespace meff::cli
