// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Text through FreeType in a real font (DejaVu Sans), instead of a pixel font whose 'g' read as
// '9' and 'p' as 'ρ'. Glyphs are placed at whole-pixel pen positions and blended by their 8-bit
// coverage with integer arithmetic, so the same text gives the same bytes on every run.
#include "meff/render.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cstdint>
#include <mutex>

#ifndef MEFF_FONT_FILE
#error "MEFF_FONT_FILE must name the font (render/CMakeLists.txt finds it)"
#endif

namespace meff::render
{

namespace
{

/// The one FreeType face, loaded on first use. FreeType objects are not thread-safe, so every
/// use holds the lock.
class Font
{
  public:
    static Font& Instance()
    {
        static Font font;
        return font;
    }

    std::mutex& Lock() { return m_mutex; }

    /// The face at `pixelSize`; throws RenderError when the font could not be loaded.
    FT_Face Face(int pixelSize)
    {
        if (m_face == nullptr)
        {
            throw RenderError(m_error);
        }
        if (pixelSize != m_pixelSize)
        {
            FT_Set_Pixel_Sizes(m_face, 0, FT_UInt(std::max(1, pixelSize)));
            m_pixelSize = pixelSize;
        }
        return m_face;
    }

  private:
    Font()
    {
        if (FT_Init_FreeType(&m_library) != 0)
        {
            m_error = "cannot start FreeType";
            return;
        }
        if (FT_New_Face(m_library, MEFF_FONT_FILE, 0, &m_face) != 0)
        {
            m_face = nullptr;
            m_error = std::string("cannot load the font ") + MEFF_FONT_FILE +
                      " (Debian: apt-get install fonts-dejavu-core)";
        }
    }
    ~Font()
    {
        if (m_face != nullptr)
        {
            FT_Done_Face(m_face);
        }
        if (m_library != nullptr)
        {
            FT_Done_FreeType(m_library);
        }
    }

    std::mutex m_mutex;
    FT_Library m_library = nullptr;
    FT_Face m_face = nullptr;
    int m_pixelSize = 0;
    std::string m_error;
};

/// The next code point of UTF-8 `text` at `i` (U+FFFD for a malformed sequence); advances `i`.
char32_t NextCodePoint(std::string_view text, std::size_t& i)
{
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char lead = byte(i);
    const std::size_t length = lead < 0x80    ? 1
                               : lead >= 0xF0 ? 4
                               : lead >= 0xE0 ? 3
                               : lead >= 0xC0 ? 2
                                              : 0;
    if (length == 0 || i + length > text.size())
    {
        ++i;
        return U'\uFFFD';
    }
    char32_t code = length == 1 ? lead : lead & (0x7F >> length);
    for (std::size_t k = 1; k < length; ++k)
    {
        if ((byte(i + k) & 0xC0) != 0x80)
        {
            ++i;
            return U'\uFFFD';
        }
        code = code << 6 | (byte(i + k) & 0x3F);
    }
    i += length;
    return code;
}

constexpr FT_Int32 kLoadFlags = FT_LOAD_TARGET_LIGHT;

/// Calls draw(glyph slot, pen x) for each character, rendered when `render` is true; returns
/// the pen's final x.
template <typename Draw>
int Walk(FT_Face face, std::string_view text, bool render, const Draw& draw)
{
    int pen = 0;
    for (std::size_t i = 0; i < text.size();)
    {
        const char32_t code = NextCodePoint(text, i);
        if (FT_Load_Char(face, FT_ULong(code), kLoadFlags | (render ? FT_LOAD_RENDER : 0)) != 0)
        {
            continue;
        }
        draw(face->glyph, pen);
        pen += int((face->glyph->advance.x + 32) >> 6);
    }
    return pen;
}

} // namespace

int TextWidth(std::string_view text, int pixelSize)
{
    Font& font = Font::Instance();
    const std::lock_guard lock(font.Lock());
    return Walk(font.Face(pixelSize), text, false, [](FT_GlyphSlot, int) {});
}

int TextHeight(int pixelSize)
{
    Font& font = Font::Instance();
    const std::lock_guard lock(font.Lock());
    const FT_Size_Metrics& metrics = font.Face(pixelSize)->size->metrics;
    return int((metrics.ascender - metrics.descender + 63) >> 6);
}

int TextAscent(int pixelSize)
{
    Font& font = Font::Instance();
    const std::lock_guard lock(font.Lock());
    return int((font.Face(pixelSize)->size->metrics.ascender + 63) >> 6);
}

void DrawText(Image& image, int x, int y, std::string_view text, Rgb color, int pixelSize)
{
    Font& font = Font::Instance();
    const std::lock_guard lock(font.Lock());
    const FT_Face face = font.Face(pixelSize);
    const int baseline = y + int((face->size->metrics.ascender + 63) >> 6);
    Walk(face, text, true,
         [&](FT_GlyphSlot glyph, int pen)
         {
             const FT_Bitmap& bitmap = glyph->bitmap;
             const int left = x + pen + glyph->bitmap_left;
             const int top = baseline - glyph->bitmap_top;
             for (int row = 0; row < int(bitmap.rows); ++row)
             {
                 for (int column = 0; column < int(bitmap.width); ++column)
                 {
                     const int px = left + column;
                     const int py = top + row;
                     if (px < 0 || py < 0 || px >= image.width || py >= image.height)
                     {
                         continue;
                     }
                     const int coverage = bitmap.buffer[row * bitmap.pitch + column];
                     if (coverage == 0)
                     {
                         continue;
                     }
                     image.Blend(px, py, color, coverage, 255);
                 }
             }
         });
}

const std::string& FontPath()
{
    static const std::string path = MEFF_FONT_FILE;
    return path;
}

} // namespace meff::render
