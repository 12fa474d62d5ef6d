#include "output_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <sys/stat.h>
#include <unistd.h>

namespace meff::cli
{

namespace
{

std::runtime_error WriteError(const std::string& path, int error)
{
    return std::runtime_error("cannot write " + path + ": " + std::strerror(error));
}

} // namespace

OutputFile::OutputFile(std::string path) : m_path(std::move(path))
{
    const std::filesystem::path destination(m_path);
    // Same directory as the destination, so that the final rename is atomic.
    m_temporaryPath =
        (destination.parent_path() / ("." + destination.filename().string() + ".XXXXXX")).string();
    const int descriptor = ::mkstemp(m_temporaryPath.data());
    if (descriptor < 0)
    {
        throw WriteError(m_path, errno);
    }
    // mkstemp makes the file private (0600); give it the permissions a new file would get.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(descriptor, 0666 & ~mask);
    m_stream = ::fdopen(descriptor, "w");
    if (m_stream == nullptr)
    {
        const int error = errno;
        ::close(descriptor);
        std::remove(m_temporaryPath.c_str());
        throw WriteError(m_path, error);
    }
}

OutputFile::~OutputFile()
{
    Discard();
}

void OutputFile::Commit()
{
    const bool writeFailed = std::ferror(m_stream) != 0;
    const int closeResult = std::fclose(m_stream);
    const int error = errno;
    m_stream = nullptr;
    if (writeFailed || closeResult != 0)
    {
        Discard();
        throw WriteError(m_path, writeFailed && closeResult == 0 ? EIO : error);
    }
    if (std::rename(m_temporaryPath.c_str(), m_path.c_str()) != 0)
    {
        const int renameError = errno;
        Discard();
        throw WriteError(m_path, renameError);
    }
    m_temporaryPath.clear();
}

void OutputFile::Discard()
{
    if (m_stream != nullptr)
    {
        std::fclose(m_stream);
        m_stream = nullptr;
    }
    if (!m_temporaryPath.empty())
    {
        std::remove(m_temporaryPath.c_str());
        m_temporaryPath.clear();
    }
}

} // namespace meff::cli
