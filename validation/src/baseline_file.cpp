// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// A baseline's bytes (meff/baseline.h): gzip around "meff-baseline 1\n", the header as one JSON
// line, then every frame in little-endian binary (doubles bit for bit, counts as 32 bits).
#include "meff/baseline.h"

#include <nlohmann/json.hpp>
#include <zlib.h>

#include <bit>
#include <cstdint>
#include <cstring>

namespace meff::validation
{

namespace
{

constexpr std::string_view kMagic = "meff-baseline";
/// Decompressed bytes past which a file is refused rather than held in memory.
constexpr std::size_t kMaxDecompressed = std::size_t(1) << 31;

class Writer
{
  public:
    void U32(std::uint32_t value)
    {
        for (int shift = 0; shift < 32; shift += 8)
        {
            m_bytes.push_back(char((value >> shift) & 0xFF));
        }
    }
    void F64(double value)
    {
        const auto bits = std::bit_cast<std::uint64_t>(value);
        U32(std::uint32_t(bits));
        U32(std::uint32_t(bits >> 32));
    }
    void Text(std::string_view text) { m_bytes += text; }
    const std::string& Bytes() const { return m_bytes; }

  private:
    std::string m_bytes;
};

/// Reads what Writer wrote; throws BaselineError "PATH: truncated" past the end.
class Reader
{
  public:
    Reader(std::string_view bytes, const std::string& path) : m_bytes(bytes), m_path(path) {}

    std::uint32_t U32()
    {
        Need(4);
        std::uint32_t value = 0;
        for (int i = 0; i < 4; ++i)
        {
            value |= std::uint32_t(std::uint8_t(m_bytes[m_at + std::size_t(i)])) << (8 * i);
        }
        m_at += 4;
        return value;
    }
    double F64()
    {
        const std::uint64_t low = U32();
        const std::uint64_t high = U32();
        return std::bit_cast<double>(low | (high << 32));
    }
    /// The bytes up to the next newline (which is consumed).
    std::string_view Line()
    {
        const std::size_t end = m_bytes.find('\n', m_at);
        if (end == std::string_view::npos)
        {
            Fail("truncated (no header line)");
        }
        const std::string_view line = m_bytes.substr(m_at, end - m_at);
        m_at = end + 1;
        return line;
    }
    /// Throws unless `count` items of `size` bytes each can still follow.
    void Need(std::size_t count, std::size_t size = 1) const
    {
        if (count > (m_bytes.size() - m_at) / size)
        {
            Fail("truncated (its frames end early)");
        }
    }
    bool AtEnd() const { return m_at == m_bytes.size(); }
    [[noreturn]] void Fail(const std::string& what) const
    {
        throw BaselineError(m_path + ": " + what + "; re-record it with --record");
    }

  private:
    std::string_view m_bytes;
    std::size_t m_at = 0;
    const std::string& m_path;
};

std::string HeaderJson(const BaselineHeader& header)
{
    const nlohmann::json json = {{"format_version", kBaselineFormatVersion},
                                 {"meff_version", header.meffVersion},
                                 {"back_end", header.backEnd},
                                 {"scene", header.scene},
                                 {"scene_hash", header.sceneHash},
                                 {"settings", nlohmann::json::parse(header.settings)},
                                 {"frames", header.frames},
                                 {"bodies", header.bodies},
                                 {"joints", header.joints}};
    return json.dump();
}

BaselineHeader ParseHeader(std::string_view line, const Reader& reader)
{
    try
    {
        const nlohmann::json json = nlohmann::json::parse(line);
        if (json.at("format_version").get<int>() != kBaselineFormatVersion)
        {
            reader.Fail("format version " + json.at("format_version").dump() +
                        ", this meff reads " + std::to_string(kBaselineFormatVersion));
        }
        BaselineHeader header;
        header.meffVersion = json.at("meff_version").get<std::string>();
        header.backEnd = json.at("back_end").get<std::string>();
        header.scene = json.at("scene").get<std::string>();
        header.sceneHash = json.at("scene_hash").get<std::string>();
        header.settings = json.at("settings").dump();
        header.frames = json.at("frames").get<int>();
        header.bodies = json.at("bodies").get<int>();
        header.joints = json.at("joints").get<int>();
        if (header.frames < 0 || header.bodies < 0 || header.joints < 0)
        {
            reader.Fail("a negative count in its header");
        }
        if (!json.at("settings").is_object())
        {
            reader.Fail("its header's settings are not an object");
        }
        return header;
    }
    catch (const nlohmann::json::exception& error)
    {
        reader.Fail(std::string("its header is not a baseline's (") + error.what() + ")");
    }
}

void WriteFrame(Writer& out, const FrameSample& frame)
{
    out.U32(std::uint32_t(frame.bodies.size()));
    for (const BodySample& body : frame.bodies)
    {
        for (const double value :
             {body.x, body.y, body.angle, body.vx, body.vy, body.angularVelocity})
        {
            out.F64(value);
        }
        out.U32(body.awake ? 1 : 0);
    }
    out.U32(std::uint32_t(frame.contacts.size()));
    for (const ContactSample& contact : frame.contacts)
    {
        const ContactKey& key = contact.key;
        for (const std::size_t index :
             {key.bodyA, key.shapeA, key.childA, key.bodyB, key.shapeB, key.childB})
        {
            out.U32(std::uint32_t(index));
        }
        out.U32(key.featureKey);
        out.F64(contact.normalImpulse);
        out.F64(contact.tangentImpulse);
    }
    out.U32(std::uint32_t(frame.joints.size()));
    for (const JointSample& joint : frame.joints)
    {
        out.F64(joint.fx);
        out.F64(joint.fy);
        out.F64(joint.torque);
    }
}

FrameSample ReadFrame(Reader& in, const BaselineHeader& header)
{
    FrameSample frame;
    if (in.U32() != std::uint32_t(header.bodies))
    {
        in.Fail("a frame's body count differs from its header's");
    }
    in.Need(std::size_t(header.bodies), 6 * 8 + 4);
    frame.bodies.resize(std::size_t(header.bodies));
    for (BodySample& body : frame.bodies)
    {
        for (double* value :
             {&body.x, &body.y, &body.angle, &body.vx, &body.vy, &body.angularVelocity})
        {
            *value = in.F64();
        }
        body.awake = in.U32() != 0;
    }
    const std::uint32_t contacts = in.U32();
    in.Need(contacts, 7 * 4 + 2 * 8);
    frame.contacts.resize(contacts);
    for (ContactSample& contact : frame.contacts)
    {
        ContactKey& key = contact.key;
        for (std::size_t* index :
             {&key.bodyA, &key.shapeA, &key.childA, &key.bodyB, &key.shapeB, &key.childB})
        {
            *index = in.U32();
        }
        key.featureKey = in.U32();
        contact.normalImpulse = in.F64();
        contact.tangentImpulse = in.F64();
    }
    if (in.U32() != std::uint32_t(header.joints))
    {
        in.Fail("a frame's joint count differs from its header's");
    }
    in.Need(std::size_t(header.joints), 3 * 8);
    frame.joints.resize(std::size_t(header.joints));
    for (JointSample& joint : frame.joints)
    {
        joint.fx = in.F64();
        joint.fy = in.F64();
        joint.torque = in.F64();
    }
    return frame;
}

/// gzip (zlib's deflate with a gzip wrapper: `zcat` reads it too).
std::string Compress(const std::string& bytes)
{
    z_stream stream{};
    if (deflateInit2(&stream, Z_DEFAULT_COMPRESSION, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) !=
        Z_OK)
    {
        throw BaselineError("zlib: cannot start compressing");
    }
    std::string out(deflateBound(&stream, uLong(bytes.size())), '\0');
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
    stream.avail_in = uInt(bytes.size());
    stream.next_out = reinterpret_cast<Bytef*>(out.data());
    stream.avail_out = uInt(out.size());
    const int status = deflate(&stream, Z_FINISH);
    out.resize(stream.total_out);
    deflateEnd(&stream);
    if (status != Z_STREAM_END)
    {
        throw BaselineError("zlib: cannot compress the baseline");
    }
    return out;
}

std::string Decompress(std::string_view bytes, const Reader& reader)
{
    if (bytes.size() < 2 || std::uint8_t(bytes[0]) != 0x1f || std::uint8_t(bytes[1]) != 0x8b)
    {
        reader.Fail("not a meff baseline (not gzip data)");
    }
    z_stream stream{};
    if (inflateInit2(&stream, 15 + 16) != Z_OK)
    {
        reader.Fail("zlib cannot start decompressing");
    }
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
    stream.avail_in = uInt(bytes.size());
    std::string out;
    int status = Z_OK;
    while (status == Z_OK && out.size() < kMaxDecompressed)
    {
        char chunk[1 << 16];
        stream.next_out = reinterpret_cast<Bytef*>(chunk);
        stream.avail_out = sizeof chunk;
        status = inflate(&stream, Z_NO_FLUSH);
        out.append(chunk, sizeof chunk - stream.avail_out);
    }
    const std::string message = stream.msg != nullptr ? stream.msg : "";
    inflateEnd(&stream);
    if (status == Z_STREAM_END && stream.avail_in == 0)
    {
        return out;
    }
    reader.Fail(status == Z_BUF_ERROR    ? "truncated (the compressed data ends early)"
                : status == Z_STREAM_END ? "corrupt (bytes after the compressed data)"
                : status == Z_OK         ? "larger than 2 GiB decompressed"
                                         : "corrupt (zlib: " + message + ")");
}

} // namespace

std::string EncodeBaseline(const Baseline& baseline)
{
    Writer out;
    out.Text(std::string(kMagic) + " " + std::to_string(kBaselineFormatVersion) + "\n");
    out.Text(HeaderJson(baseline.header) + "\n");
    for (const FrameSample& frame : baseline.frames)
    {
        WriteFrame(out, frame);
    }
    return Compress(out.Bytes());
}

Baseline DecodeBaseline(std::string_view bytes, const std::string& path)
{
    const Reader outer(bytes, path);
    const std::string text = Decompress(bytes, outer);
    Reader in(text, path);
    const std::string_view magic = in.Line();
    if (magic.substr(0, kMagic.size() + 1) != std::string(kMagic) + " ")
    {
        in.Fail("not a meff baseline");
    }
    if (magic != std::string(kMagic) + " " + std::to_string(kBaselineFormatVersion))
    {
        in.Fail("format " + std::string(magic.substr(kMagic.size() + 1)) + ", this meff reads " +
                std::to_string(kBaselineFormatVersion));
    }
    Baseline baseline;
    baseline.header = ParseHeader(in.Line(), in);
    for (int frame = 0; frame <= baseline.header.frames; ++frame)
    {
        baseline.frames.push_back(ReadFrame(in, baseline.header));
    }
    if (!in.AtEnd())
    {
        in.Fail("corrupt (bytes after its last frame)");
    }
    return baseline;
}

} // namespace meff::validation
