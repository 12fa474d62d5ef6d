// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Output files: regular files appear whole or not at all; anything else is written through.
#pragma once

#include <cstdio>
#include <string>

namespace meff::cli
{

/// An output named on the command line.
///
/// A regular file (or a new one) is written to a hidden temporary file in its directory
/// (".NAME.meff-HOST-PID.XXXXXX") and renamed over it on Commit(), so a reader never sees half
/// a file and a failed or interrupted run leaves no file behind: the temporary is removed if the
/// object is destroyed uncommitted, and by RemoveTemporariesOnSignal's handler if the process
/// is interrupted. One left by a process that could not remove it (kill -9) is removed by the
/// next OutputFile in that folder, once that process no longer runs. The file is fsynced before
/// the rename and its folder after, so that it is whole or absent after a crash of the machine
/// too. A symbolic link is followed: its final target is replaced, the link itself kept.
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

/// Installs handlers for SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGXCPU, SIGALRM, SIGUSR1 and SIGUSR2
/// that remove every temporary file of an uncommitted OutputFile (and of RegisterTemporary),
/// say so in one line on stderr, and then let the signal end the process as it would have (the
/// shell sees 128 + the signal's number). Also ignores SIGPIPE and SIGXFSZ, so that a closed
/// pipe and a file-size limit are write errors said in words (exit status 1).
void RemoveTemporariesOnSignal();

/// Makes every allocation failure, anywhere in the process (a thread, a destructor, a JSON copy
/// unwinding), end it with "meff: out of memory" on stderr and exit status 1 (the run failed),
/// its temporary files removed, instead of an abort.
void EndOnOutOfMemory();

/// Registers another temporary path for removal by the signal handler (a file a child process
/// writes, say); returns the slot to pass to UnregisterTemporary, or -1 when the list is full.
/// `path` must stay alive and unchanged until unregistered.
int RegisterTemporary(const std::string& path);
void UnregisterTemporary(int slot);

} // namespace meff::cli
