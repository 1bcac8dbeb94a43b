// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Author(s): The PR-star octree project

#ifndef CGAL_PR_STAR_OCTREE_INTERNAL_COMPACT_TETRAHEDRA_H
#define CGAL_PR_STAR_OCTREE_INTERNAL_COMPACT_TETRAHEDRA_H

// The compact tetrahedron array of the octree (named parameter `compact_tetrahedra`).
//
// The octree's array T is sorted by smallest vertex, in the depth-first vertex order of the leaves,
// so a tetrahedron's other vertices are mostly close to its smallest one.  The encoding keeps every
// tetrahedron exactly (its four vertices in their order):
// - the smallest vertex is implicit: `counts[v]` is the number of tetrahedra whose smallest vertex
//   is `v` (one byte; 255 means "look it up in `big_counts`");
// - each tetrahedron is one control byte and three little-endian differences: bits 0-1 of the
//   control byte give the position of the smallest vertex `m`, bits 2-7 the byte lengths of the
//   differences `x - m - 1` of the three others, taken cyclically after `m`;
// - every `block_size` tetrahedra, an entry of `blocks` holds the byte offset of the block, its
//   first smallest vertex and how many tetrahedra of that vertex come before the block, and `steps`
//   the byte lengths of its first three runs of `step_size` records (the vertex at the start of a
//   run follows from `counts`), so that tetrahedron `t` is found by skipping at most
//   `step_size - 1` records.
// A cursor decodes consecutive tetrahedra in one pass; `decode_range()` decodes a range faster.

#include <CGAL/PR_star_octree/internal/huge_pages.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace PR_star_octree {
namespace internal {

template <class Index>
class Compact_tetrahedra {
  static_assert(std::is_unsigned<Index>::value, "");

public:
  using Tetrahedron = std::array<Index, 4>;
  static constexpr std::size_t block_size = 64;
  // a block's records in runs of `step_size`: the byte length of each of its first three runs is
  // kept, so that a seek skips at most `step_size - 1` records
  static constexpr std::size_t step_size = 16;
  static constexpr std::size_t steps_per_block = block_size / step_size - 1;

  // the byte lengths of the codes 0..3 of a difference
  static constexpr unsigned length_of(unsigned code) {
    return sizeof(Index) <= 4 ? code + 1 : (code == 3 ? 8u : 1u << code);
  }

  struct Block {
    std::uint64_t offset; // of the block's first record in `bytes`
    Index vertex;         // the smallest vertex of its first tetrahedron
    Index rank;           // the number of tetrahedra of `vertex` before the block
  };

  Compact_tetrahedra() { make_record_lengths(); }

  // Encodes `nt` tetrahedra of vertices in `[0, nv)`, sorted by smallest vertex (non-decreasing),
  // each with four distinct vertices.  Two passes over `T`: the first checks it, counts and sizes
  // the records, the second writes them into bytes allocated once at their exact size (a growing
  // array would hold up to three times the final bytes at its last reallocation).
  // \throws std::invalid_argument otherwise
  void assign(const Tetrahedron* T, std::size_t nt, std::size_t nv) {
    size_ = nt;
    std::vector<unsigned char>().swap(bytes_);
    blocks_.clear();
    steps_.assign(steps_per_block * (nt / block_size + (nt % block_size != 0 ? 1 : 0)), Step(0));
    big_counts_.clear();
    assign_huge(counts_, nv, static_cast<unsigned char>(0));
    std::vector<std::pair<Index, std::size_t>> big; // vertices owning 255 or more tetrahedra
    Index current = 0;
    std::size_t rank = 0, total = 0;
    blocks_.reserve(nt / block_size + 1);
    for (std::size_t t = 0; t < nt; ++t) {
      const Tetrahedron& c = T[t];
      const Index m = (std::min)((std::min)(c[0], c[1]), (std::min)(c[2], c[3]));
      if (m >= nv || (t > 0 && m < current))
        throw std::invalid_argument("Compact_tetrahedra: the tetrahedra are not sorted by smallest vertex");
      if (t == 0 || m != current) {
        current = m;
        rank = 0;
      }
      if (t % block_size == 0) blocks_.push_back(Block{total, m, static_cast<Index>(rank)});
      ++rank;
      if (counts_[m] < 255) {
        if (++counts_[m] == 255) big.emplace_back(m, 255);
      } else
        ++big.back().second;
      if (c[0] == c[1] || c[0] == c[2] || c[0] == c[3] || c[1] == c[2] || c[1] == c[3] || c[2] == c[3])
        throw std::invalid_argument("Compact_tetrahedra: a tetrahedron with a repeated vertex");
      if ((std::max)((std::max)(c[0], c[1]), (std::max)(c[2], c[3])) >= nv)
        throw std::invalid_argument("Compact_tetrahedra: a tetrahedron with an out-of-range vertex");
      std::uint64_t d[3];
      total += record_length_[encode(c, d)];
    }
    // 8 bytes of padding: a difference is always read as one 8-byte load
    resize_huge(bytes_, total + 8, static_cast<unsigned char>(0));
    unsigned char* out = bytes_.data();
    for (std::size_t t = 0; t < nt; ++t) {
      std::uint64_t d[3];
      const unsigned control = encode(T[t], d);
      note_step(t, static_cast<std::uint64_t>(out - bytes_.data()));
      out = write_record(out, control, d);
    }
    CGAL_assertion(static_cast<std::size_t>(out - bytes_.data()) == total);
    blocks_.shrink_to_fit();
    big_counts_.reserve(big.size());
    for (const auto& b : big) big_counts_.emplace_back(b.first, static_cast<Index>(b.second));
  }

  // Streaming encoding, for tetrahedra that arrive in slabs (the streaming construction):
  // `start()` takes the number of tetrahedra of which each vertex is the smallest (`counts[v]`,
  // `nv` of them) and the exact number of bytes of the records (the sum of `record_length()`), then
  // `append()` encodes consecutive tetrahedra in order, and `finish()` checks that all came.
  // \throws std::invalid_argument on tetrahedra that do not match the counts
  template <class Count>
  void start(const Count* counts, std::size_t nv, std::size_t nt, std::size_t total_bytes) {
    size_ = nt;
    std::vector<unsigned char>().swap(bytes_);
    blocks_.clear();
    big_counts_.clear();
    assign_huge(counts_, nv, static_cast<unsigned char>(0));
    std::size_t sum = 0;
    for (std::size_t v = 0; v < nv; ++v) {
      const std::size_t c = static_cast<std::size_t>(counts[v]);
      sum += c;
      if (c < 255)
        counts_[v] = static_cast<unsigned char>(c);
      else {
        counts_[v] = 255;
        big_counts_.emplace_back(static_cast<Index>(v), static_cast<Index>(c));
      }
    }
    if (sum != nt) throw std::invalid_argument("Compact_tetrahedra::start: the counts do not add up to nt");
    resize_huge(bytes_, total_bytes + 8, static_cast<unsigned char>(0));
    blocks_.resize(nt / block_size + (nt % block_size != 0 ? 1 : 0));
    steps_.assign(steps_per_block * blocks_.size(), Step(0));
    stream_ = Stream{};
  }
  void append(const Tetrahedron* T, std::size_t n) {
    Stream& st = stream_;
    for (std::size_t i = 0; i < n; ++i) {
      const Tetrahedron& c = T[i];
      const Index m = (std::min)((std::min)(c[0], c[1]), (std::min)(c[2], c[3]));
      if (st.t >= size_ || (st.t > 0 && m < st.vertex))
        throw std::invalid_argument("Compact_tetrahedra::append: a tetrahedron out of order or too many");
      if (st.t == 0 || m != st.vertex) {
        st.vertex = m;
        st.rank = 0;
      }
      if (st.t % block_size == 0)
        blocks_[st.t / block_size] = Block{st.offset, m, static_cast<Index>(st.rank)};
      std::uint64_t d[3];
      const unsigned control = encode(c, d);
      const std::size_t len = record_length_[control];
      if (st.offset + len > bytes_.size() - 8)
        throw std::invalid_argument("Compact_tetrahedra::append: more bytes than announced");
      note_step(st.t, st.offset);
      write_record(bytes_.data() + st.offset, control, d);
      st.offset += len;
      ++st.rank;
      ++st.t;
    }
  }
  void finish() const {
    if (stream_.t != size_ || stream_.offset + 8 != bytes_.size())
      throw std::invalid_argument("Compact_tetrahedra::finish: not every tetrahedron came");
  }
  // the bytes of the record of tetrahedron `c` (the same for any order of its vertices)
  std::size_t record_length(const Tetrahedron& c) const {
    std::uint64_t d[3];
    return record_length_[encode(c, d)];
  }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }

  // the bytes held (capacities)
  std::size_t memory_bytes() const {
    return bytes_.capacity() + counts_.capacity() + blocks_.capacity() * sizeof(Block) +
           steps_.capacity() * sizeof(Step) + big_counts_.capacity() * sizeof(std::pair<Index, Index>);
  }

  // the number of tetrahedra whose smallest vertex is `v`
  std::size_t count(Index v) const {
    const unsigned char c = counts_[v];
    if (c < 255) return c;
    const auto it = std::lower_bound(big_counts_.begin(), big_counts_.end(), v,
                                     [](const std::pair<Index, Index>& a, Index x) { return a.first < x; });
    return it->second;
  }

  // Asks the processor to fetch what a seek to tetrahedron `t` reads, ahead of time (for a list
  // of tetrahedra decoded one after the other): `near == false`, the block's entry and run lengths;
  // `near == true` (later, once those are in cache), the records of its run and the counts of its
  // first vertex.
  void prefetch(std::size_t t, bool near) const {
#if defined(__GNUC__) || defined(__clang__)
    if (t >= size_) return;
    const std::size_t block = t / block_size, steps = (t % block_size) / step_size;
    if (!near) {
      __builtin_prefetch(blocks_.data() + block);
      __builtin_prefetch(steps_.data() + steps_per_block * block);
      return;
    }
    const Block& b = blocks_[block];
    const std::uint64_t offset = b.offset + sum_steps(block, steps);
    __builtin_prefetch(bytes_.data() + offset);
    __builtin_prefetch(bytes_.data() + offset + 64);
    __builtin_prefetch(counts_.data() + b.vertex);
#else
    (void)t;
    (void)near;
#endif
  }

  // Decodes consecutive tetrahedra from any position.
  class Cursor {
  public:
    Cursor() = default;
    // positioned on tetrahedron `t` (`t == size()` is the end)
    Cursor(const Compact_tetrahedra& a, std::size_t t) : a_(&a) { seek(t); }

    std::size_t position() const { return t_; }
    void seek(std::size_t t) {
      if (t_ != npos && t >= t_ && t - t_ < step_size && t_ < a_->size_ && t <= a_->size_) {
        skip(t - t_);
        return;
      }
      t_ = t;
      if (t >= a_->size_) return;
      const std::size_t block = t / block_size, steps = (t % block_size) / step_size;
      const Block& b = a_->blocks_[block];
      offset_ = b.offset;
      vertex_ = b.vertex;
      rank_ = b.rank;
      t_ = t - t % block_size;
      if (steps > 0) { // whole runs: their bytes from the steps, their vertices from the counts
        offset_ += a_->sum_steps(block, steps);
        t_ += steps * step_size;
        rank_ += steps * step_size;
        std::size_t n;
        while (rank_ >= (n = a_->count(vertex_))) {
          rank_ -= n;
          ++vertex_;
        }
      }
      skip(t - t_);
    }
    // the tetrahedron at the position; \pre `position() < size()`
    Tetrahedron operator*() const {
      Tetrahedron c;
      a_->decode_record(a_->bytes_.data() + offset_, vertex_, c);
      return c;
    }
    Cursor& operator++() {
      offset_ += a_->record_length_[a_->bytes_[offset_]];
      ++t_;
      ++rank_;
      if (--left_ == 0 && t_ < a_->size_) settle();
      return *this;
    }

  private:
    friend class Compact_tetrahedra;
    static constexpr std::size_t npos = ~std::size_t(0);
    static bool host_is_little_endian() {
      const std::uint16_t probe = 1;
      unsigned char first;
      std::memcpy(&first, &probe, 1);
      return first == 1;
    }
    // moves on to the vertex that owns the tetrahedron at the position
    void settle() {
      std::size_t n;
      while (rank_ >= (n = a_->count(vertex_))) {
        ++vertex_;
        rank_ = 0;
      }
      left_ = n - rank_;
    }
    void skip(std::size_t n) {
      settle();
      while (n > 0) {
        const std::size_t k = (std::min)(n, left_);
        for (std::size_t i = 0; i < k; ++i) offset_ += a_->record_length_[a_->bytes_[offset_]];
        t_ += k;
        rank_ += k;
        left_ -= k;
        n -= k;
        if (left_ == 0 && t_ < a_->size_) settle();
      }
    }

    const Compact_tetrahedra* a_ = nullptr;
    std::size_t t_ = npos;
    std::uint64_t offset_ = 0;
    Index vertex_ = 0;
    std::size_t rank_ = 0;
    std::size_t left_ = 0; // the tetrahedra of `vertex_` from the position on
  };

  // tetrahedron `t` (random access: at most `step_size - 1` records skipped)
  Tetrahedron operator[](std::size_t t) const {
    return *Cursor(*this, t);
  }

  // Decodes the tetrahedra `[first, last)` into `out[0, last - first)`: the records of one smallest
  // vertex after the other, each from its control byte alone (a cursor checks for the next vertex
  // at every record).  Returns the end of what was written.
  Tetrahedron* decode_range(std::size_t first, std::size_t last, Tetrahedron* out) const {
    if (first >= last) return out;
    const Cursor c(*this, first);
    const unsigned char* r = bytes_.data() + c.offset_;
    Index v = c.vertex_;
    std::size_t left = c.left_, n = last - first;
    for (;;) {
      const std::size_t k = (std::min)(n, left);
      for (std::size_t i = 0; i < k; ++i) r += decode_record(r, v, *out++);
      n -= k;
      if (n == 0) return out;
      do left = count(++v);
      while (left == 0);
    }
  }

  // decodes the tetrahedra `[first, last)` into `out`
  template <class OutputIterator>
  OutputIterator decode(std::size_t first, std::size_t last, OutputIterator out) const {
    if (first >= last) return out;
    Cursor c(*this, first);
    for (std::size_t t = first; t < last; ++t, ++c) *out++ = *c;
    return out;
  }

private:
  // The control byte of tetrahedron `c` (the position of its smallest vertex, the byte-length code
  // of each difference) and the three differences to its smallest vertex, in `d`.
  static unsigned encode(const Tetrahedron& c, std::uint64_t (&d)[3]) {
    int p = 0;
    for (int k = 1; k < 4; ++k)
      if (c[k] < c[p]) p = k;
    unsigned control = static_cast<unsigned>(p);
    for (int k = 0; k < 3; ++k) {
      d[k] = static_cast<std::uint64_t>(c[(p + 1 + k) & 3] - c[p] - 1);
      // the shortest length code that holds d[k] (lengths 1-4 bytes, or 1, 2, 4, 8), without branches
      const std::uint64_t x = d[k];
      const unsigned code = sizeof(Index) <= 4
                                ? unsigned(x > 0xffu) + unsigned(x > 0xffffu) + unsigned(x > 0xffffffu)
                                : unsigned(x > 0xffu) + unsigned(x > 0xffffu) + unsigned(x > 0xffffffffu);
      control |= code << (2 + 2 * k);
    }
    return control;
  }

  // Writes the record of control byte `control` and differences `d` at `out`; returns its end.
  // Each difference is stored as a whole `std::uint64_t` (little-endian), the next one written over
  // its unused bytes: the 8 bytes of padding after the last record keep this in bounds.
  static unsigned char* write_record(unsigned char* out, unsigned control, const std::uint64_t (&d)[3]) {
    *out++ = static_cast<unsigned char>(control);
    for (int k = 0; k < 3; ++k) {
      const unsigned len = length_of((control >> (2 + 2 * k)) & 3u);
      if (Cursor::host_is_little_endian())
        std::memcpy(out, &d[k], sizeof d[k]);
      else
        for (unsigned b = 0; b < len; ++b) out[b] = static_cast<unsigned char>(d[k] >> (8 * b));
      out += len;
    }
    return out;
  }

  // records the byte length of the run of `step_size` records ending before tetrahedron `t`,
  // whose record starts at byte `offset`
  void note_step(std::size_t t, std::uint64_t offset) {
    const std::size_t i = t % block_size;
    if (i == 0 || i % step_size != 0) return;
    const std::size_t block = t / block_size, run = i / step_size - 1;
    const std::uint64_t start =
        run == 0 ? blocks_[block].offset : blocks_[block].offset + sum_steps(block, run);
    steps_[steps_per_block * block + run] = static_cast<Step>(offset - start);
  }
  std::uint64_t sum_steps(std::size_t block, std::size_t runs) const {
    std::uint64_t s = 0;
    for (std::size_t i = 0; i < runs; ++i) s += steps_[steps_per_block * block + i];
    return s;
  }

  void make_record_lengths() {
    for (unsigned control = 0; control < 256; ++control) {
      unsigned n = 1;
      Layout& l = layout_[control];
      for (unsigned k = 0; k < 3; ++k) {
        const unsigned code = (control >> (2 + 2 * k)) & 3u;
        l.at[k] = static_cast<unsigned char>(n);
        l.mask[k] = length_of(code) >= sizeof(Unit) ? ~Unit(0) : (Unit(1) << (8 * length_of(code))) - 1;
        n += length_of(code);
      }
      record_length_[control] = static_cast<unsigned char>(n);
    }
  }

  // The record at `r` as the tetrahedron `c` of smallest vertex `v`; returns its length.  A
  // difference is one load of `Unit` (the 8 bytes of padding make it safe) and a mask.
  unsigned decode_record(const unsigned char* r, Index v, Tetrahedron& c) const {
    const unsigned control = r[0];
    const Layout& l = layout_[control];
    const unsigned p = control & 3u;
    c[p] = v;
    c[(p + 1) & 3] = static_cast<Index>(v + 1 + (load_unit(r + l.at[0]) & l.mask[0]));
    c[(p + 2) & 3] = static_cast<Index>(v + 1 + (load_unit(r + l.at[1]) & l.mask[1]));
    c[(p + 3) & 3] = static_cast<Index>(v + 1 + (load_unit(r + l.at[2]) & l.mask[2]));
    if constexpr (sizeof(Index) <= 4) { // 1 + (c0 + 1) + (c1 + 1) + (c2 + 1): no lookup in the chain
      const unsigned x = control >> 2;
      return 4 + (x & 3u) + ((x >> 2) & 3u) + (x >> 4);
    } else
      return record_length_[control];
  }
  // a little-endian difference: 4 bytes for 32-bit indices (at most 4 bytes long), else 8
  using Unit = std::conditional_t<(sizeof(Index) <= 4), std::uint32_t, std::uint64_t>;
  static Unit load_unit(const unsigned char* r) {
    Unit d;
    std::memcpy(&d, r, sizeof d);
    if (!Cursor::host_is_little_endian()) {
      Unit y = 0;
      for (unsigned i = 0; i < sizeof d; ++i) y = static_cast<Unit>((y << 8) | ((d >> (8 * i)) & 0xff));
      d = y;
    }
    return d;
  }
  struct Layout { // where the differences of a record are, and their masks, by its control byte
    unsigned char at[3];
    Unit mask[3];
  };
  Layout layout_[256];

  struct Stream { // where `append()` is
    std::size_t t = 0, rank = 0;
    std::uint64_t offset = 0;
    Index vertex = 0;
  };
  Stream stream_;
  std::size_t size_ = 0;
  std::vector<unsigned char> bytes_;
  std::vector<unsigned char> counts_;
  std::vector<std::pair<Index, Index>> big_counts_;
  std::vector<Block> blocks_;
  // the byte length of a run of `step_size` records: at most 16 x 13 bytes with 32-bit indices
  using Step = std::conditional_t<(sizeof(Index) <= 4), std::uint8_t, std::uint16_t>;
  std::vector<Step> steps_;
  unsigned char record_length_[256];
};

// The tetrahedron array of the octree as a random-access range of `std::array<Index, 4>` values,
// plain or compact.  Its iterator decodes consecutive tetrahedra in one pass; `operator[]` is random
// access (a few records skipped in the compact form).
template <class Index>
class Tetrahedra_view {
public:
  using Tetrahedron = std::array<Index, 4>;
  using Compact = Compact_tetrahedra<Index>;

  class iterator {
  public:
    using iterator_category = std::random_access_iterator_tag;
    using value_type = Tetrahedron;
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = Tetrahedron; // by value: the compact form has no array to point into

    iterator() = default;
    iterator(const Tetrahedra_view* v, std::size_t t) : plain_(v->plain_), t_(t) {
      if (v->compact_ != nullptr) cursor_ = typename Compact::Cursor(*v->compact_, t);
      compact_ = v->compact_;
    }
    Tetrahedron operator*() const { return compact_ ? *cursor_ : plain_[t_]; }
    Tetrahedron operator[](difference_type d) const { return *(*this + d); }
    iterator& operator++() {
      ++t_;
      if (compact_) ++cursor_;
      return *this;
    }
    iterator operator++(int) {
      iterator c = *this;
      ++*this;
      return c;
    }
    iterator& operator--() { return *this -= 1; }
    iterator operator--(int) {
      iterator c = *this;
      --*this;
      return c;
    }
    iterator& operator+=(difference_type d) {
      t_ = static_cast<std::size_t>(static_cast<difference_type>(t_) + d);
      if (compact_) cursor_.seek(t_);
      return *this;
    }
    iterator& operator-=(difference_type d) { return *this += -d; }
    friend iterator operator+(iterator a, difference_type d) { return a += d; }
    friend iterator operator+(difference_type d, iterator a) { return a += d; }
    friend iterator operator-(iterator a, difference_type d) { return a -= d; }
    friend difference_type operator-(const iterator& a, const iterator& b) {
      return static_cast<difference_type>(a.t_) - static_cast<difference_type>(b.t_);
    }
    friend bool operator==(const iterator& a, const iterator& b) { return a.t_ == b.t_; }
    friend bool operator!=(const iterator& a, const iterator& b) { return a.t_ != b.t_; }
    friend bool operator<(const iterator& a, const iterator& b) { return a.t_ < b.t_; }
    friend bool operator>(const iterator& a, const iterator& b) { return a.t_ > b.t_; }
    friend bool operator<=(const iterator& a, const iterator& b) { return a.t_ <= b.t_; }
    friend bool operator>=(const iterator& a, const iterator& b) { return a.t_ >= b.t_; }

  private:
    const Tetrahedron* plain_ = nullptr;
    const Compact* compact_ = nullptr;
    typename Compact::Cursor cursor_;
    std::size_t t_ = 0;
  };
  using const_iterator = iterator;
  using value_type = Tetrahedron;
  using size_type = std::size_t;

  Tetrahedra_view(const Tetrahedron* plain, std::size_t n) : plain_(plain), n_(n) {}
  explicit Tetrahedra_view(const Compact& compact) : compact_(&compact), n_(compact.size()) {}

  std::size_t size() const { return n_; }
  bool empty() const { return n_ == 0; }
  bool is_compact() const { return compact_ != nullptr; }
  /// the plain array, or `nullptr` in the compact form
  const Tetrahedron* data() const { return compact_ ? nullptr : plain_; }
  Tetrahedron operator[](std::size_t t) const { return compact_ ? (*compact_)[t] : plain_[t]; }
  iterator begin() const { return iterator(this, 0); }
  iterator end() const { return iterator(this, n_); }

private:
  const Tetrahedron* plain_ = nullptr;
  const Compact* compact_ = nullptr;
  std::size_t n_ = 0;
};

// The tetrahedra of one leaf's list, decoded once from the compact array, indexed by their index
// in T: `operator[](t)` for `t` in the list (the owned range directly, a shared one through a
// hash table from index to position filled at decoding).  Plain arrays are indexed through a
// pointer instead.
template <class Index>
class Leaf_cells {
public:
  using Tetrahedron = std::array<Index, 4>;

  // decodes the tetrahedra `shared` (increasing), then the owned range, of `T`
  template <class Shared>
  void decode(const Compact_tetrahedra<Index>& T, const Shared& shared, std::pair<Index, Index> owned) {
    ids_.clear();
    n_shared_ = static_cast<std::size_t>(std::distance(shared.begin(), shared.end()));
    const std::size_t n = n_shared_ + static_cast<std::size_t>(owned.second - owned.first);
    if (cells_.size() < n) cells_.resize(n); // the buffer is only written; it grows, never shrinks
    Tetrahedron* out = cells_.data();
    if (n_shared_ > 0) {
      // The shared tetrahedra are scattered over T: what the seeks read is fetched 8 and 16
      // tetrahedra ahead, so that the cache misses of one overlap the decoding of others.
      ids_.assign(shared.begin(), shared.end());
      typename Compact_tetrahedra<Index>::Cursor c(T, ids_[0]);
      for (std::size_t i = 0; i < n_shared_; ++i) {
        if (i + 16 < n_shared_) T.prefetch(ids_[i + 16], false);
        if (i + 8 < n_shared_) T.prefetch(ids_[i + 8], true);
        c.seek(ids_[i]);
        *out++ = *c;
      }
    }
    owned_ = owned;
    T.decode_range(owned.first, owned.second, out);
    index_shared();
  }
  // tetrahedron `t` of T; \pre `t` is in the list
  const Tetrahedron& operator[](Index t) const {
    std::size_t hint = n_shared_;
    return find(t, hint);
  }
  // The same, for one thread reading the list mostly in its order: a shared tetrahedron is looked
  // for first next to the previous one found, then in the hash table.
  class Reader {
  public:
    explicit Reader(const Leaf_cells& cells) : cells_(&cells) {}
    const Tetrahedron& operator[](Index t) const { return cells_->find(t, next_); }

  private:
    const Leaf_cells* cells_;
    mutable std::size_t next_ = 0;
  };

  std::size_t memory_bytes() const {
    return ids_.capacity() * sizeof(Index) + cells_.capacity() * sizeof(Tetrahedron) +
           slots_.capacity() * sizeof(std::uint32_t);
  }

private:
  std::size_t slot_of(Index t) const {
    return static_cast<std::size_t>((static_cast<std::uint64_t>(t) * 0x9E3779B97F4A7C15ull) >> shift_);
  }
  // Open addressing with linear probing, at most half full: slot -> 1 + position in `ids_`, 0 if
  // empty.  A binary search among a few thousand shared indices took as long as the rest of
  // `count_simplices()` in a leaf.
  void index_shared() {
    if (n_shared_ == 0) return;
    unsigned bits = 4;
    while ((std::size_t(1) << bits) < 2 * n_shared_) ++bits;
    shift_ = 64 - bits;
    mask_ = (std::size_t(1) << bits) - 1;
    slots_.assign(mask_ + 1, 0);
    for (std::size_t i = 0; i < n_shared_; ++i) {
      std::size_t s = slot_of(ids_[i]);
      while (slots_[s] != 0) s = (s + 1) & mask_;
      slots_[s] = static_cast<std::uint32_t>(i + 1);
    }
  }

  // `next`: where to look first for a shared tetrahedron, then the position after the one found
  const Tetrahedron& find(Index t, std::size_t& next) const {
    const std::size_t d = static_cast<Index>(t - owned_.first);
    if (d < static_cast<std::size_t>(owned_.second - owned_.first)) return cells_[n_shared_ + d];
    if (next >= n_shared_ || ids_[next] != t) {
      std::size_t s = slot_of(t);
      while (ids_[slots_[s] - 1] != t) s = (s + 1) & mask_;
      next = slots_[s] - 1;
    }
    return cells_[next++];
  }

  std::vector<Index> ids_;
  std::vector<Tetrahedron> cells_;
  std::size_t n_shared_ = 0;
  std::vector<std::uint32_t> slots_;
  std::size_t mask_ = 0;
  unsigned shift_ = 64;

  std::pair<Index, Index> owned_{0, 0};
};

} // namespace internal
} // namespace PR_star_octree
} // namespace CGAL

#endif // CGAL_PR_STAR_OCTREE_INTERNAL_COMPACT_TETRAHEDRA_H
