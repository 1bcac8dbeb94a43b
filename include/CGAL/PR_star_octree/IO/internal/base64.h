// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_IO_INTERNAL_BASE64_H
#define CGAL_PR_STAR_OCTREE_IO_INTERNAL_BASE64_H

// Base64 (RFC 4648, standard alphabet) streaming decoder and encoder, as used by VTK XML files.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace CGAL {
namespace PR_star_octree {
namespace IO {
namespace internal {

/// Decodes base64 text incrementally.  Whitespace is skipped.  A quantum padded with `=` ends a
/// block, and decoding goes on with the next quantum: the concatenation of separately encoded
/// blocks (VTK writes the header of a data array either in the same base64 stream as the data or
/// as a block of its own) decodes to the concatenation of the bytes.
class Base64_decoder {
public:
  explicit Base64_decoder(std::string_view text) : text_(text) {}

  /// Fills `out[0..n)`; returns `false` when the text ends or holds an invalid character first
  /// (then `error()` tells which).
  bool read(unsigned char* out, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
      if (avail_ == 0) {
        // fast path: whole groups of 4 plain characters straight to the output
        while (n - i >= 3 && text_.size() - pos_ >= 4) {
          const int a = value(text_[pos_]), b = value(text_[pos_ + 1]), c = value(text_[pos_ + 2]),
                    d = value(text_[pos_ + 3]);
          if ((a | b | c | d) < 0) break;
          const std::uint32_t bits = (std::uint32_t(a) << 18) | (std::uint32_t(b) << 12) |
                                     (std::uint32_t(c) << 6) | std::uint32_t(d);
          out[i] = static_cast<unsigned char>(bits >> 16);
          out[i + 1] = static_cast<unsigned char>(bits >> 8);
          out[i + 2] = static_cast<unsigned char>(bits);
          i += 3;
          pos_ += 4;
        }
        if (i == n) return true;
        if (!decode_quantum()) return false;
      }
      out[i] = buf_[3 - avail_];
      --avail_;
    }
    return true;
  }

  /// An upper bound of the number of bytes that can still be decoded.
  std::size_t max_remaining_bytes() const { return avail_ + (text_.size() - pos_) / 4 * 3 + 3; }

  const char* error() const { return error_; }
  /// the first character of the text not decoded yet
  const char* position() const { return text_.data() + pos_; }
  /// offset in the text of the problem reported by `error()`
  std::size_t error_offset() const { return error_pos_; }

  static int value(char c) {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  }

private:
  bool decode_quantum() {
    int v[4];
    int n = 0, pad = 0;
    while (n < 4) {
      while (pos_ < text_.size() && is_ws(text_[pos_])) ++pos_;
      if (pos_ >= text_.size()) {
        if (n == 0) {
          error_ = "the base64 data is shorter than announced";
        } else {
          error_ = "the base64 data ends in the middle of a 4-character group";
        }
        error_pos_ = pos_;
        return false;
      }
      const char c = text_[pos_];
      if (c == '=') {
        if (n < 2) return fail("misplaced '=' in the base64 data");
        ++pad;
        v[n++] = 0;
      } else {
        const int x = value(c);
        if (x < 0) return fail("invalid character in the base64 data");
        if (pad > 0) return fail("misplaced '=' in the base64 data");
        v[n++] = x;
      }
      ++pos_;
    }
    const std::uint32_t bits = (std::uint32_t(v[0]) << 18) | (std::uint32_t(v[1]) << 12) |
                               (std::uint32_t(v[2]) << 6) | std::uint32_t(v[3]);
    const int bytes = 3 - pad;
    // right-align the decoded bytes in buf_ so that read() takes buf_[3 - avail_]
    unsigned char all[3] = {static_cast<unsigned char>(bits >> 16), static_cast<unsigned char>(bits >> 8),
                            static_cast<unsigned char>(bits)};
    for (int i = 0; i < bytes; ++i) buf_[3 - bytes + i] = all[i];
    avail_ = bytes;
    return true;
  }
  bool fail(const char* message) {
    error_ = message;
    error_pos_ = pos_;
    return false;
  }
  static bool is_ws(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  unsigned char buf_[3] = {0, 0, 0};
  int avail_ = 0;
  const char* error_ = nullptr;
  std::size_t error_pos_ = 0;
};

/// Encodes bytes to base64 appended to a string, as one stream (`finish()` pads the end).
class Base64_encoder {
public:
  explicit Base64_encoder(std::string& out) : out_(out) {}

  void write(const unsigned char* data, std::size_t n) {
    std::size_t i = 0;
    while (len_ != 0 && i < n) { // complete the pending group first
      buf_[len_++] = data[i++];
      if (len_ == 3) emit();
    }
    // whole groups straight to the output
    const std::size_t groups = (n - i) / 3;
    if (groups != 0) {
      static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
      std::size_t at = out_.size();
      out_.resize(at + 4 * groups);
      char* o = &out_[at];
      for (std::size_t g = 0; g < groups; ++g, i += 3, o += 4) {
        const std::uint32_t bits =
            (std::uint32_t(data[i]) << 16) | (std::uint32_t(data[i + 1]) << 8) | std::uint32_t(data[i + 2]);
        o[0] = alphabet[(bits >> 18) & 63];
        o[1] = alphabet[(bits >> 12) & 63];
        o[2] = alphabet[(bits >> 6) & 63];
        o[3] = alphabet[bits & 63];
      }
    }
    for (; i < n; ++i) buf_[len_++] = data[i]; // at most 2 left
  }
  void finish() {
    if (len_ == 0) return;
    const int n = len_;
    for (int i = n; i < 3; ++i) buf_[i] = 0;
    len_ = 3;
    emit();
    for (int i = n + 1; i < 4; ++i) out_[out_.size() - 4 + i] = '=';
  }

private:
  void emit() {
    static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const std::uint32_t bits =
        (std::uint32_t(buf_[0]) << 16) | (std::uint32_t(buf_[1]) << 8) | std::uint32_t(buf_[2]);
    out_ += alphabet[(bits >> 18) & 63];
    out_ += alphabet[(bits >> 12) & 63];
    out_ += alphabet[(bits >> 6) & 63];
    out_ += alphabet[bits & 63];
    len_ = 0;
  }
  std::string& out_;
  unsigned char buf_[3] = {0, 0, 0};
  int len_ = 0;
};

} // namespace internal
} // namespace IO
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_IO_INTERNAL_BASE64_H
