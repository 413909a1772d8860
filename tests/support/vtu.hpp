#pragma once
// Reading back the DataArrays of the .vtu files Tunica writes (output/vtk_writer.cpp), in each
// of its formats, written here from VTK's file-format description and independent of the writer:
//   format="binary"    inline base64 of (UInt64 byte count, values),
//   format="ascii"     the values as text,
//   format="appended"  a block at `offset` after the '_' of <AppendedData encoding="raw">:
//                      (UInt64 byte count, values), or, with compressor="vtkZLibDataCompressor",
//                      UInt64 [chunks, chunk size, last partial chunk size, compressed sizes…]
//                      followed by the zlib-compressed chunks.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace tunica::test {

inline std::string vtu_attribute(const std::string& tag, const std::string& name) {
  const auto at = tag.find(" " + name + "=\"");
  if (at == std::string::npos) return "";
  const auto begin = at + name.size() + 3;
  return tag.substr(begin, tag.find('"', begin) - begin);
}

/// The raw bytes of appended block at `offset` (decompressed if the file names the zlib compressor).
inline std::string appended_block(const std::string& vtu, std::uint64_t offset) {
  const auto data = vtu.find('_', vtu.find("<AppendedData encoding=\"raw\">")) + 1;
  const auto u64 = [&](std::uint64_t at) {
    std::uint64_t x = 0;
    std::memcpy(&x, vtu.data() + data + at, 8);
    return x;
  };
  const std::string head = vtu.substr(0, vtu.find("<UnstructuredGrid>"));
  if (vtu_attribute(head, "compressor").empty()) return vtu.substr(data + offset + 8, u64(offset));
  const std::uint64_t chunks = u64(offset), chunk_bytes = u64(offset + 8), last = u64(offset + 16);
  std::string out;
  std::uint64_t at = offset + 24 + 8 * chunks;
  for (std::uint64_t c = 0; c < chunks; ++c) {
    const std::uint64_t packed = u64(offset + 24 + 8 * c);
    uLongf n = (c + 1 == chunks && last != 0) ? last : chunk_bytes;
    std::string chunk(n, '\0');
    EXPECT_EQ(uncompress(reinterpret_cast<Bytef*>(chunk.data()), &n, reinterpret_cast<const Bytef*>(vtu.data() + data + at), packed), Z_OK);
    out += chunk.substr(0, n);
    at += packed;
  }
  return out;
}

inline std::string base64_decode(const std::string& text) {
  std::string bytes;
  unsigned buffer = 0;
  int bits = 0;
  const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  for (char ch : text) {
    const char* p = ch ? std::strchr(alphabet, ch) : nullptr;
    if (!p) continue;
    buffer = (buffer << 6) | static_cast<unsigned>(p - alphabet);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      bytes.push_back(static_cast<char>((buffer >> bits) & 0xff));
    }
  }
  return bytes;
}

/// Decodes DataArray `name` of values of type T, whatever the format of the file.
template <class T>
std::vector<T> decode_array(const std::string& vtu, const std::string& name) {
  const auto start = vtu.rfind("<DataArray", vtu.find("Name=\"" + name + "\""));
  const auto close = vtu.find('>', start);
  const std::string tag = vtu.substr(start, close - start + 1);
  const std::string format = vtu_attribute(tag, "format");
  std::vector<T> v;
  if (format == "ascii") {
    std::istringstream in(vtu.substr(close + 1, vtu.find("</DataArray>", close) - close - 1));
    for (std::string w; in >> w;) v.push_back(static_cast<T>(std::is_floating_point_v<T> ? std::stod(w) : std::stoll(w)));
    return v;
  }
  std::string bytes;
  if (format == "appended") {
    bytes = appended_block(vtu, std::stoull(vtu_attribute(tag, "offset")));
  } else {
    EXPECT_EQ(format, "binary") << name;
    bytes = base64_decode(vtu.substr(close + 1, vtu.find("</DataArray>", close) - close - 1));
    std::uint64_t count = 0;
    std::memcpy(&count, bytes.data(), 8);
    EXPECT_EQ(count + 8, bytes.size()) << name;
    bytes = bytes.substr(8);
  }
  EXPECT_EQ(bytes.size() % sizeof(T), 0u) << name;
  v.resize(bytes.size() / sizeof(T));
  if (!v.empty()) std::memcpy(v.data(), bytes.data(), v.size() * sizeof(T));
  return v;
}

/// A Float64 DataArray.
inline std::vector<double> decode_float64(const std::string& vtu, const std::string& name) {
  return decode_array<double>(vtu, name);
}

}  // namespace tunica::test
