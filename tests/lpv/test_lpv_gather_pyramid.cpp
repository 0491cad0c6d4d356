// The gather's pyramid of sources (shaders/shared/lpv_gather.h): which level each source is
// gathered at, for every gathering cell. The shaders and the CPU reference walk the same
// windows; this checks the walk itself: every cell of the grid is gathered exactly once, a
// block always more than its own side away, and a cell reads a bounded number of records
// however large the grid.
#include "shaders/shared/lpv_sh.h"
#include "shaders/shared/lpv_gather.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace {

struct Walk {
  std::vector<int> times_gathered;  // per source cell, x-fastest
  int records = 0;                  // records read (blocks visited)
  int nearest_block = 1 << 30;      // the least Chebyshev distance, in cells, of a block above level 0
  int levels = 0;                   // levels climbed
};

// The windows lpv_gather.comp walks for one gathering cell, each block visited marked on the
// cells it holds.
Walk walk(glm::ivec3 cell, glm::ivec3 dims) {
  Walk w;
  w.times_gathered.assign(std::size_t(dims.x * dims.y * dims.z), 0);
  bool last = false;
  for (int level = 0; !last; ++level) {
    const gpu::LpvGatherWindow window = gpu::lpv_gather_window(cell, level, dims);
    last = window.last;
    ++w.levels;
    for (int bz = window.lo.z; bz <= window.hi.z; ++bz)
      for (int by = window.lo.y; by <= window.hi.y; ++by)
        for (int bx = window.lo.x; bx <= window.hi.x; ++bx) {
          const glm::ivec3 block(bx, by, bz);
          if (gpu::lpv_gather_gathered_finer(block, cell, level)) continue;
          ++w.records;
          const glm::ivec3 first = block * (1 << level);
          const glm::ivec3 end = glm::min(first + glm::ivec3(1 << level), dims);
          for (int z = first.z; z < end.z; ++z)
            for (int y = first.y; y < end.y; ++y)
              for (int x = first.x; x < end.x; ++x) {
                ++w.times_gathered[std::size_t(x + dims.x * (y + dims.y * z))];
                if (level > 0) {
                  const glm::ivec3 apart = glm::abs(glm::ivec3(x, y, z) - cell);
                  w.nearest_block = std::min(w.nearest_block, std::max({apart.x, apart.y, apart.z}));
                }
              }
        }
  }
  return w;
}

TEST(GatherPyramid, EveryCellIsGatheredExactlyOnceAndBlocksStayFarOff) {
  for (const glm::ivec3 dims : {glm::ivec3(1), glm::ivec3(5, 1, 1), glm::ivec3(2, 3, 4), glm::ivec3(8),
                                glm::ivec3(13, 6, 9), glm::ivec3(16)}) {
    SCOPED_TRACE(std::to_string(dims.x) + "x" + std::to_string(dims.y) + "x" + std::to_string(dims.z));
    for (int z = 0; z < dims.z; ++z)
      for (int y = 0; y < dims.y; ++y)
        for (int x = 0; x < dims.x; ++x) {
          const Walk w = walk({x, y, z}, dims);
          ASSERT_EQ(std::count(w.times_gathered.begin(), w.times_gathered.end(), 1), std::ptrdiff_t(w.times_gathered.size()))
              << "cell " << x << "," << y << "," << z << " gathers some source twice or not at all";
          // Above level 0 the nearest cell of a block is more than a block's side (2^L >= 2) off.
          if (w.levels > 1 && w.nearest_block != 1 << 30) {
            ASSERT_GE(w.nearest_block, 3);
          }
        }
  }
}

// The records a cell reads grow with the levels, not with the cells: at most 6^3 at level 0
// and 6^3 - 3^3 at each level above, however large the grid (a grid of every lit cell read
// 110592 records a cell at 48^3).
TEST(GatherPyramid, ACellReadsAFewHundredRecordsWhateverTheGrid) {
  for (const int side : {16, 24, 48}) {
    const glm::ivec3 dims(side);
    int most = 0;
    for (const glm::ivec3 cell : {glm::ivec3(0), glm::ivec3(side / 2), glm::ivec3(side - 1, 0, side / 3)}) {
      const Walk w = walk(cell, dims);
      most = std::max(most, w.records);
      EXPECT_LE(w.records, 216 + (w.levels - 1) * (216 - 27));
    }
    std::printf("%d^3 cells: at most %d records read by a cell\n", side, most);
    EXPECT_LT(most, 1000);
  }
}

TEST(GatherPyramid, RecordsFitTheirLevels) {
  const glm::ivec3 dims(13, 6, 9);
  EXPECT_EQ(gpu::lpv_gather_levels(dims), 5);  // 13 -> 7 -> 4 -> 2 -> 1
  EXPECT_EQ(gpu::lpv_gather_level_first(dims, 1), 13 * 6 * 9);
  EXPECT_EQ(gpu::lpv_gather_level_blocks(dims, 1), 7 * 3 * 5);
  EXPECT_EQ(gpu::lpv_gather_records(dims), 13 * 6 * 9 + 7 * 3 * 5 + 4 * 2 * 3 + 2 * 1 * 2 + 1);
  EXPECT_EQ(gpu::lpv_gather_records(glm::ivec3(1)), 1);
}

}  // namespace
