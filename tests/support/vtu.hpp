#pragma once
// Reading back the inline binary DataArrays of the .vtu files Tunica writes (output/vtk_writer.cpp).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace tunica::test {

/// Decodes VTK's inline binary DataArray `name` of values of type T: base64 of a UInt64 byte
/// count followed by the values.
template <class T>
std::vector<T> decode_array(const std::string& vtu, const std::string& name) {
  const auto begin = vtu.find('>', vtu.find("Name=\"" + name + "\"")) + 1;
  std::string text = vtu.substr(begin, vtu.find("</DataArray>", begin) - begin);
  std::string bytes;
  unsigned buffer = 0;
  int bits = 0;
  for (char ch : text) {
    const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const char* p = std::strchr(alphabet, ch);
    if (ch == '=' || ch == '\n' || !p || ch == 0) continue;
    buffer = (buffer << 6) | static_cast<unsigned>(p - alphabet);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      bytes.push_back(static_cast<char>((buffer >> bits) & 0xff));
    }
  }
  std::uint64_t count = 0;
  std::memcpy(&count, bytes.data(), 8);
  EXPECT_EQ(count + 8, bytes.size()) << name;
  std::vector<T> v(count / sizeof(T));
  std::memcpy(v.data(), bytes.data() + 8, count);
  return v;
}

/// A Float64 DataArray.
inline std::vector<double> decode_float64(const std::string& vtu, const std::string& name) {
  return decode_array<double>(vtu, name);
}

}  // namespace tunica::test
