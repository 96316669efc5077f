// Copyright (c) 2026 The Surface_voronoi_diagram authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A self-contained PNG writer (8-bit RGB), for the manual's figures (make_figures.cpp) and
// the tests; not part of the library. The deflate stream is our own: LZ77 over a 32 KiB
// window with hash chains, coded with the fixed Huffman tables of RFC 1951. Rendered
// diagrams are large areas of flat colour, which this compresses 10-30x; a dependency on
// libpng or zlib for that would make the doc build link one more library.

#ifndef SVD_FIGURES_PNG_WRITER_H
#define SVD_FIGURES_PNG_WRITER_H

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace svd_figures {

/// Bad input of the renderer or the PNG writer (options, mesh, image); the message says which.
class Input_error : public std::invalid_argument
{
public:
  explicit Input_error(const std::string& what) : std::invalid_argument(what) {}
};

/// A PNG file that cannot be opened or written.
class Write_error : public std::runtime_error
{
public:
  explicit Write_error(const std::string& what) : std::runtime_error(what) {}
};

/// An 8-bit RGB image, rows from top to bottom, as `render_arrangement()` returns it.
struct Image
{
  std::size_t width = 0;
  std::size_t height = 0;
  /// `3 * width * height` bytes: red, green, blue of each pixel, row by row from the top
  std::vector<unsigned char> rgb;

  Image() {}
  /// an image of the given size filled with one colour
  Image(std::size_t w, std::size_t h, std::array<unsigned char, 3> fill = {{255, 255, 255}})
    : width(w), height(h), rgb(3 * w * h)
  {
    for(std::size_t k = 0; k < w * h; ++k)
      for(int c = 0; c < 3; ++c) rgb[3 * k + c] = fill[c];
  }
  /// the colour of pixel (`x`, `y`), `y = 0` being the top row
  std::array<unsigned char, 3> pixel(std::size_t x, std::size_t y) const
  {
    const std::size_t k = 3 * (y * width + x);
    return {{rgb[k], rgb[k + 1], rgb[k + 2]}};
  }
  void set_pixel(std::size_t x, std::size_t y, std::array<unsigned char, 3> c)
  {
    const std::size_t k = 3 * (y * width + x);
    rgb[k] = c[0]; rgb[k + 1] = c[1]; rgb[k + 2] = c[2];
  }
};

namespace internal {

inline std::uint32_t crc32_update(std::uint32_t crc, const unsigned char* data, std::size_t n)
{
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for(std::uint32_t i = 0; i < 256; ++i)
    {
      std::uint32_t c = i;
      for(int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  for(std::size_t i = 0; i < n; ++i) crc = table[(crc ^ data[i]) & 0xFF] ^ (crc >> 8);
  return crc;
}

inline std::uint32_t adler32(const std::vector<unsigned char>& data)
{
  std::uint32_t a = 1, b = 0;
  for(unsigned char byte : data)
  {
    a = (a + byte) % 65521u;
    b = (b + a) % 65521u;
  }
  return (b << 16) | a;
}

// Deflate writes its bit fields least significant bit first, except Huffman codes,
// which are defined most significant bit first and therefore reversed here.
class Deflate_bits
{
public:
  explicit Deflate_bits(std::vector<unsigned char>& out) : m_out(out) {}
  void put(std::uint32_t bits, int count)
  {
    m_acc |= std::uint64_t(bits) << m_n;
    m_n += count;
    while(m_n >= 8)
    {
      m_out.push_back(static_cast<unsigned char>(m_acc & 0xFF));
      m_acc >>= 8;
      m_n -= 8;
    }
  }
  void put_code(std::uint32_t code, int length)
  {
    std::uint32_t reversed = 0;
    for(int k = 0; k < length; ++k) reversed |= ((code >> k) & 1u) << (length - 1 - k);
    put(reversed, length);
  }
  void flush()
  {
    if(m_n > 0) m_out.push_back(static_cast<unsigned char>(m_acc & 0xFF));
    m_acc = 0;
    m_n = 0;
  }

private:
  std::vector<unsigned char>& m_out;
  std::uint64_t m_acc = 0;
  int m_n = 0;
};

// the fixed literal/length code of RFC 1951, 3.2.6
inline void put_literal_or_length(Deflate_bits& bits, unsigned symbol)
{
  if(symbol < 144) bits.put_code(0x30 + symbol, 8);
  else if(symbol < 256) bits.put_code(0x190 + symbol - 144, 9);
  else if(symbol < 280) bits.put_code(symbol - 256, 7);
  else bits.put_code(0xC0 + symbol - 280, 8);
}

inline void put_match(Deflate_bits& bits, unsigned length, unsigned distance)
{
  static const unsigned length_base[29] = {3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27,
                                           31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
  static const int length_extra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                       2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
  static const unsigned distance_base[30] = {1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129,
                                             193, 257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097,
                                             6145, 8193, 12289, 16385, 24577};
  static const int distance_extra[30] = {0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6,
                                         6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};
  int l = 28;
  while(length_base[l] > length) --l;
  put_literal_or_length(bits, 257 + l);
  bits.put(length - length_base[l], length_extra[l]);
  int d = 29;
  while(distance_base[d] > distance) --d;
  bits.put_code(d, 5);
  bits.put(distance - distance_base[d], distance_extra[d]);
}

// A zlib stream (RFC 1950) holding one fixed-Huffman deflate block. Greedy LZ77: at each
// position the longest match among the last `max_chain` positions with the same 3-byte hash.
inline std::vector<unsigned char> zlib_compress(const std::vector<unsigned char>& data)
{
  const std::size_t window = 32768, max_chain = 48, min_match = 3, max_match = 258;
  std::vector<unsigned char> out = {0x78, 0x01};   // deflate, 32 KiB window, no dictionary
  Deflate_bits bits(out);
  bits.put(1, 1);   // final block
  bits.put(1, 2);   // fixed Huffman codes
  const std::size_t n = data.size(), hash_size = std::size_t(1) << 15;
  std::vector<std::int64_t> head(hash_size, -1), previous(n, -1);
  auto hash_at = [&](std::size_t i) {
    return ((std::size_t(data[i]) << 10) ^ (std::size_t(data[i + 1]) << 5) ^ data[i + 2]) & (hash_size - 1);
  };
  auto insert = [&](std::size_t i) {
    if(i + min_match > n) return;
    const std::size_t h = hash_at(i);
    previous[i] = head[h];
    head[h] = std::int64_t(i);
  };
  std::size_t i = 0;
  while(i < n)
  {
    std::size_t best_length = 0, best_distance = 0;
    if(i + min_match <= n)
    {
      std::int64_t candidate = head[hash_at(i)];
      const std::size_t limit = (std::min)(max_match, n - i);
      for(std::size_t chain = 0; candidate >= 0 && chain < max_chain; ++chain)
      {
        const std::size_t c = std::size_t(candidate);
        if(i - c > window) break;
        std::size_t length = 0;
        while(length < limit && data[c + length] == data[i + length]) ++length;
        if(length > best_length)
        {
          best_length = length;
          best_distance = i - c;
          if(length == limit) break;
        }
        candidate = previous[c];
      }
    }
    if(best_length >= min_match)
    {
      put_match(bits, unsigned(best_length), unsigned(best_distance));
      for(std::size_t k = 0; k < best_length; ++k) insert(i + k);
      i += best_length;
    }
    else
    {
      put_literal_or_length(bits, data[i]);
      insert(i);
      ++i;
    }
  }
  put_literal_or_length(bits, 256);   // end of block
  bits.flush();
  const std::uint32_t a = adler32(data);
  for(int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<unsigned char>((a >> shift) & 0xFF));
  return out;
}

inline void put_u32(std::vector<unsigned char>& out, std::uint32_t v)
{
  for(int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<unsigned char>((v >> shift) & 0xFF));
}

inline void put_chunk(std::vector<unsigned char>& out, const char* type, const std::vector<unsigned char>& data)
{
  put_u32(out, std::uint32_t(data.size()));
  const std::size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data.begin(), data.end());
  const std::uint32_t crc = crc32_update(0xFFFFFFFFu, out.data() + start, out.size() - start) ^ 0xFFFFFFFFu;
  put_u32(out, crc);
}

} // namespace internal

/// The bytes of `image` as a PNG file (8-bit RGB, no interlacing, compressed).
/// \throws Input_error if the image is empty or its buffer does not match its size
inline std::vector<unsigned char> encode_PNG(const Image& image)
{
  if(image.width == 0 || image.height == 0 || image.width > 0x7FFFFFFF || image.height > 0x7FFFFFFF)
    throw Input_error("encode_PNG: the image is empty or too large (" + std::to_string(image.width) + " x "
                      + std::to_string(image.height) + ")");
  if(image.rgb.size() != 3 * image.width * image.height)
    throw Input_error("encode_PNG: the image holds " + std::to_string(image.rgb.size()) + " bytes, "
                      + std::to_string(3 * image.width * image.height) + " expected");
  std::vector<unsigned char> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::vector<unsigned char> header;
  internal::put_u32(header, std::uint32_t(image.width));
  internal::put_u32(header, std::uint32_t(image.height));
  header.insert(header.end(), {8, 2, 0, 0, 0});   // 8 bits, RGB, deflate, adaptive filters, no interlace
  internal::put_chunk(out, "IHDR", header);
  // filter type 0 on every row: flat colour already gives long LZ77 matches
  std::vector<unsigned char> raw;
  raw.reserve(image.height * (1 + 3 * image.width));
  for(std::size_t y = 0; y < image.height; ++y)
  {
    raw.push_back(0);
    raw.insert(raw.end(), image.rgb.begin() + 3 * y * image.width, image.rgb.begin() + 3 * (y + 1) * image.width);
  }
  internal::put_chunk(out, "IDAT", internal::zlib_compress(raw));
  internal::put_chunk(out, "IEND", {});
  return out;
}

/// Writes `image` to `filename` as a PNG file.
/// \throws Input_error for an empty image
/// \throws Write_error if the file cannot be written
inline void write_PNG(const std::string& filename, const Image& image)
{
  const std::vector<unsigned char> bytes = encode_PNG(image);
  std::ofstream os(filename, std::ios::binary);
  if(!os) throw Write_error("cannot open '" + filename + "' for writing");
  os.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  if(!os) throw Write_error("failed to write '" + filename + "'");
}

} // namespace svd_figures

#endif // SVD_FIGURES_PNG_WRITER_H
