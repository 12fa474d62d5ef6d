// Output files that appear whole or not at all.
#pragma once

#include <cstdio>
#include <string>

namespace meff::cli
{

/// Writes to a hidden temporary file in the destination's directory and renames it over the
/// destination on Commit(), so a reader never sees half a file and a failed run leaves no
/// file behind. The temporary is removed if the object is destroyed uncommitted.
class OutputFile
{
  public:
    /// Creates the temporary file; throws std::runtime_error saying why it cannot.
    explicit OutputFile(std::string path);
    ~OutputFile();
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    std::FILE* Stream() { return m_stream; }
    const std::string& Path() const { return m_path; }

    /// Flushes, closes and renames into place; throws std::runtime_error on any failure (the
    /// temporary is then removed and the destination left untouched).
    void Commit();

  private:
    void Discard();

    std::string m_path;
    std::string m_temporaryPath;
    std::FILE* m_stream = nullptr;
};

} // namespace meff::cli
