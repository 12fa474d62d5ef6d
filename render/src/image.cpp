// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Images: pixels, rectangles blended over them, and stitching. Text is drawn by text.cpp.
#include "meff/render.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace meff::render
{

Image::Image(int width_, int height_, Rgb fill) : width(width_), height(height_)
{
    pixels.resize(std::size_t(width) * std::size_t(height) * 3);
    for (std::size_t i = 0; i < pixels.size(); i += 3)
    {
        pixels[i] = fill.r;
        pixels[i + 1] = fill.g;
        pixels[i + 2] = fill.b;
    }
}

Rgb Image::At(int x, int y) const
{
    const std::size_t i = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3;
    return {pixels[i], pixels[i + 1], pixels[i + 2]};
}

void Image::Set(int x, int y, Rgb color)
{
    const std::size_t i = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3;
    pixels[i] = color.r;
    pixels[i + 1] = color.g;
    pixels[i + 2] = color.b;
}

std::uint8_t Image::AlphaAt(int x, int y) const
{
    return alpha.empty() ? std::uint8_t(255)
                         : alpha[std::size_t(y) * std::size_t(width) + std::size_t(x)];
}

void Image::Blend(int x, int y, Rgb color, int weight, int scale)
{
    const Rgb under = At(x, y);
    if (alpha.empty())
    {
        // Integers, rounded, so that the result does not depend on floating-point rounding
        // modes.
        const auto mix = [&](std::uint8_t below, std::uint8_t over)
        { return std::uint8_t((below * (scale - weight) + over * weight + scale / 2) / scale); };
        Set(x, y, {mix(under.r, color.r), mix(under.g, color.g), mix(under.b, color.b)});
        return;
    }
    // "Over" with straight (not premultiplied) colours: the result's opacity is the new
    // layer's plus what shows through it of the old.
    std::uint8_t& opacity = alpha[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    const double top = double(weight) / scale;
    const double below = opacity / 255.0 * (1 - top);
    const double total = top + below;
    if (total <= 0)
    {
        return;
    }
    const auto mix = [&](std::uint8_t b, std::uint8_t over)
    { return std::uint8_t(std::lround((over * top + b * below) / total)); };
    Set(x, y, {mix(under.r, color.r), mix(under.g, color.g), mix(under.b, color.b)});
    opacity = std::uint8_t(std::lround(total * 255));
}

void FillRect(Image& image, int x, int y, int width, int height, Rgb color, double alpha)
{
    // A weight out of 256.
    const int a = std::clamp(int(std::lround(alpha * 256)), 0, 256);
    for (int py = std::max(0, y); py < std::min(image.height, y + height); ++py)
    {
        for (int px = std::max(0, x); px < std::min(image.width, x + width); ++px)
        {
            image.Blend(px, py, color, a, 256);
        }
    }
}

Image StitchHorizontally(std::span<const Image> images, int gap, Rgb gapColor)
{
    int width = 0;
    int height = 0;
    for (const Image& image : images)
    {
        width += image.width;
        height = std::max(height, image.height);
    }
    if (!images.empty())
    {
        width += gap * int(images.size() - 1);
    }
    Image strip(width, height, gapColor);
    int left = 0;
    for (const Image& image : images)
    {
        for (int y = 0; y < image.height; ++y)
        {
            std::copy_n(image.pixels.begin() + std::ptrdiff_t(y) * image.width * 3, image.width * 3,
                        strip.pixels.begin() + (std::ptrdiff_t(y) * width + left) * 3);
        }
        left += image.width + gap;
    }
    return strip;
}

} // namespace meff::render
