// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_ATLAS_CELL_BITMAP_H
#define CGAL_SMP_INTERNAL_ATLAS_CELL_BITMAP_H

// Cells of the packing's grid, a bit per cell. The cells a chart covers: triangles are
// rasterized into it span by span, it is widened by the gutter with word operations, and read
// back as runs of cells, so that no list of spans is sorted and merged per row. The cells taken
// so far: whether a chart's span meets one is a test of a word or two.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

class Cell_bitmap
{
public:
  Cell_bitmap(long rows, long columns)
    : rows_(rows), columns_(columns), words_((columns + 63) / 64), bits_(std::size_t(rows * words_), 0)
  {}

  long rows() const { return rows_; }

  // Adds cleared rows up to `rows` rows.
  void add_rows(long rows)
  {
    if(rows <= rows_) return;
    rows_ = rows;
    bits_.resize(std::size_t(rows_ * words_), 0);
  }

  // The first set cell of `row` in [first, end) (0 <= first < end <= columns), else `end`.
  long first_set(long row, long first, long end) const { return next(word(row, 0), first, end, true); }

  // The first cleared cell of `row` from `c` on (the number of columns if none): the end of
  // the run of set cells that holds `c`.
  long run_end(long row, long c) const { return next(word(row, 0), c, columns_, false); }

  // Sets the cells [first, last] of `row`.
  void set(long row, long first, long last)
  {
    std::uint64_t* w = word(row, 0);
    const long a = first / 64, b = last / 64;
    const std::uint64_t from = ~std::uint64_t(0) << (first % 64), to = ~std::uint64_t(0) >> (63 - last % 64);
    if(a == b) { w[a] |= from & to; return; }
    w[a] |= from;
    for(long i = a + 1; i < b; ++i) w[i] = ~std::uint64_t(0);
    w[b] |= to;
  }

  // Every set cell (r, c) also sets the cells (r + i, c + j) for 0 <= i, j <= `d`, within the
  // bitmap: the OR of the bitmap shifted by 0 to d, doubling the covered shifts at each pass.
  void dilate(long d)
  {
    for(long covered = 1; covered <= d; ) { // shifts 0 to covered - 1 are in
      const long step = (std::min)(covered, d + 1 - covered);
      for(long r = 0; r < rows_; ++r)
        shift_or(word(r, 0), step);
      covered += step;
    }
    for(long covered = 1; covered <= d; ) {
      const long step = (std::min)(covered, d + 1 - covered);
      for(long r = rows_ - 1; r >= step; --r) { // downwards: row r - step is still as it was
        std::uint64_t* to = word(r, 0);
        const std::uint64_t* from = word(r - step, 0);
        for(long i = 0; i < words_; ++i) to[i] |= from[i];
      }
      covered += step;
    }
  }

  // The runs of set cells of `row`, in order, as half-open spans [first, second).
  void runs(long row, std::vector<std::pair<long, long> >& out) const
  {
    out.clear();
    const std::uint64_t* w = word(row, 0);
    long c = 0;
    while(c < columns_) {
      c = next(w, c, columns_, true);
      if(c >= columns_) break;
      const long end = next(w, c, columns_, false);
      out.emplace_back(c, end);
      c = end;
    }
  }

private:
  std::uint64_t* word(long row, long i) { return bits_.data() + row * words_ + i; }
  const std::uint64_t* word(long row, long i) const { return bits_.data() + row * words_ + i; }

  // the row's bits OR-ed with themselves moved `s` cells right (0 < s): towards higher columns
  void shift_or(std::uint64_t* w, long s) const
  {
    const long whole = s / 64, part = s % 64;
    for(long i = words_ - 1; i >= whole; --i) {
      std::uint64_t moved = w[i - whole] << part;
      if(part > 0 && i - whole - 1 >= 0) moved |= w[i - whole - 1] >> (64 - part);
      w[i] |= moved;
    }
  }

  // the first cell in [c, end) whose bit is `set` (c < end <= columns_), else `end`
  long next(const std::uint64_t* w, long c, long end, bool set) const
  {
    long i = c / 64;
    const long last = (end - 1) / 64;
    std::uint64_t x = (set ? w[i] : ~w[i]) & (~std::uint64_t(0) << (c % 64));
    while(x == 0) {
      if(++i > last) return end;
      x = set ? w[i] : ~w[i];
    }
    return (std::min)(end, i * 64 + lowest_bit(x));
  }

  // the position of the lowest set bit of `x` (not 0)
  static long lowest_bit(std::uint64_t x)
  {
#if defined(__GNUC__) || defined(__clang__)
    return long(__builtin_ctzll(x));
#else
    long bit = 0;
    while(!(x & 1)) { x >>= 1; ++bit; }
    return bit;
#endif
  }

  long rows_, columns_, words_;
  std::vector<std::uint64_t> bits_;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_ATLAS_CELL_BITMAP_H
