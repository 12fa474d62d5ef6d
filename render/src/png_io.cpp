// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// PNG encoding and decoding with libpng's simplified API (png_image), which needs no setjmp
// error handling in C++ code: failures come back as a status and a message.
#include "meff/render.h"

#include <png.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <sys/stat.h>
#include <unistd.h>

namespace meff::render
{

namespace
{

png_image Describe(const Image& image)
{
    png_image description;
    std::memset(&description, 0, sizeof description);
    description.version = PNG_IMAGE_VERSION;
    description.width = png_uint_32(image.width);
    description.height = png_uint_32(image.height);
    description.format = image.HasAlpha() ? PNG_FORMAT_RGBA : PNG_FORMAT_RGB;
    return description;
}

/// The bytes libpng reads: the pixels as they are, or interleaved with the alpha plane.
std::vector<std::uint8_t> Interleaved(const Image& image)
{
    std::vector<std::uint8_t> rgba(image.alpha.size() * 4);
    for (std::size_t i = 0; i < image.alpha.size(); ++i)
    {
        std::copy_n(image.pixels.begin() + std::ptrdiff_t(i * 3), 3,
                    rgba.begin() + std::ptrdiff_t(i * 4));
        rgba[i * 4 + 3] = image.alpha[i];
    }
    return rgba;
}

std::string Reason(const png_image& image)
{
    return image.message[0] != '\0' ? image.message : "libpng failed";
}

} // namespace

std::vector<std::uint8_t> EncodePng(const Image& image)
{
    if (image.width <= 0 || image.height <= 0)
    {
        throw RenderError("cannot encode an empty image as PNG");
    }
    png_image description = Describe(image);
    const std::vector<std::uint8_t> rgba = Interleaved(image);
    const std::uint8_t* source = image.HasAlpha() ? rgba.data() : image.pixels.data();
    // First call: how many bytes; second: the bytes. libpng writes no time or text chunk
    // unless asked, so the output depends on the pixels alone.
    png_alloc_size_t size = 0;
    if (!png_image_write_to_memory(&description, nullptr, &size, 0, source, 0, nullptr))
    {
        throw RenderError("cannot encode PNG: " + Reason(description));
    }
    std::vector<std::uint8_t> bytes(size);
    if (!png_image_write_to_memory(&description, bytes.data(), &size, 0, source, 0, nullptr))
    {
        throw RenderError("cannot encode PNG: " + Reason(description));
    }
    bytes.resize(size);
    return bytes;
}

Image DecodePng(std::span<const std::uint8_t> bytes)
{
    png_image description;
    std::memset(&description, 0, sizeof description);
    description.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&description, bytes.data(), bytes.size()))
    {
        throw RenderError("cannot read PNG: " + Reason(description));
    }
    const bool alpha = (description.format & PNG_FORMAT_FLAG_ALPHA) != 0;
    description.format = alpha ? PNG_FORMAT_RGBA : PNG_FORMAT_RGB;
    Image image;
    image.width = int(description.width);
    image.height = int(description.height);
    std::vector<std::uint8_t> bytesRead(PNG_IMAGE_SIZE(description));
    if (!png_image_finish_read(&description, nullptr, bytesRead.data(), 0, nullptr))
    {
        png_image_free(&description);
        throw RenderError("cannot read PNG: " + Reason(description));
    }
    if (!alpha)
    {
        image.pixels = std::move(bytesRead);
        return image;
    }
    const std::size_t count = std::size_t(image.width) * std::size_t(image.height);
    image.pixels.resize(count * 3);
    image.alpha.resize(count);
    for (std::size_t i = 0; i < count; ++i)
    {
        std::copy_n(bytesRead.begin() + std::ptrdiff_t(i * 4), 3,
                    image.pixels.begin() + std::ptrdiff_t(i * 3));
        image.alpha[i] = bytesRead[i * 4 + 3];
    }
    return image;
}

Image ReadPng(const std::string& path)
{
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (file == nullptr)
    {
        throw RenderError("cannot read " + path + ": " + std::strerror(errno));
    }
    std::vector<std::uint8_t> bytes;
    std::uint8_t buffer[65536];
    std::size_t count = 0;
    while ((count = std::fread(buffer, 1, sizeof buffer, file)) > 0)
    {
        bytes.insert(bytes.end(), buffer, buffer + count);
    }
    const bool failed = std::ferror(file) != 0;
    std::fclose(file);
    if (failed)
    {
        throw RenderError("cannot read " + path);
    }
    try
    {
        return DecodePng(bytes);
    }
    catch (const RenderError& error)
    {
        throw RenderError(path + ": " + error.what());
    }
}

void WritePng(const std::string& path, const Image& image)
{
    const std::vector<std::uint8_t> bytes = EncodePng(image);
    WriteFileAtomically(
        path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

void WriteFileAtomically(const std::string& path, std::string_view bytes)
{
    const std::filesystem::path destination(path);
    // Beside the destination, so that the rename is atomic: a reader (or a crash) never sees
    // half a PNG.
    std::string temporary =
        (destination.parent_path() / ("." + destination.filename().string() + ".XXXXXX")).string();
    const int descriptor = ::mkstemp(temporary.data());
    if (descriptor < 0)
    {
        throw RenderError("cannot write " + path + ": " + std::strerror(errno));
    }
    // mkstemp makes the file private (0600); give it the permissions a new file would get.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(descriptor, 0666 & ~mask);
    std::size_t written = 0;
    int error = 0;
    while (written < bytes.size())
    {
        const ssize_t n = ::write(descriptor, bytes.data() + written, bytes.size() - written);
        if (n < 0)
        {
            if (errno == EINTR)
            {
                continue;
            }
            error = errno;
            break;
        }
        written += std::size_t(n);
    }
    if (::close(descriptor) != 0 && error == 0)
    {
        error = errno;
    }
    if (error == 0 && std::rename(temporary.c_str(), path.c_str()) != 0)
    {
        error = errno;
    }
    if (error != 0)
    {
        std::remove(temporary.c_str());
        throw RenderError("cannot write " + path + ": " + std::strerror(error));
    }
}

} // namespace meff::render
