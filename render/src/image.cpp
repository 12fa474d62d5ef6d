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

void FillRect(Image& image, int x, int y, int width, int height, Rgb color, double alpha)
{
    // Integer weights out of 256, so that the result does not depend on floating-point
    // rounding modes.
    const int a = std::clamp(int(std::lround(alpha * 256)), 0, 256);
    const auto mix = [a](std::uint8_t under, std::uint8_t over)
    { return std::uint8_t((under * (256 - a) + over * a + 128) >> 8); };
    for (int py = std::max(0, y); py < std::min(image.height, y + height); ++py)
    {
        for (int px = std::max(0, x); px < std::min(image.width, x + width); ++px)
        {
            const Rgb under = image.At(px, py);
            image.Set(px, py,
                      {mix(under.r, color.r), mix(under.g, color.g), mix(under.b, color.b)});
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
