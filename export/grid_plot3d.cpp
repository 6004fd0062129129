#include "export/grid_plot3d.hpp"

#include <cstdio>
#include <memory>

#include "export/atomic_file.hpp"

namespace cg::io {

void write_plot3d(const std::filesystem::path& file, const grid::MultiBlockGrid& grid, double z) {
  write_atomically(file, [&](const std::filesystem::path& tmp) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(tmp.c_str(), "w"), &std::fclose);
    if (!f) throw ExportError("cannot open " + tmp.string() + " for writing");
    std::FILE* out = f.get();
    std::fprintf(out, "%zu\n", grid.blocks.size());
    for (const grid::Block& b : grid.blocks) std::fprintf(out, "%d %d 1\n", b.ni + 1, b.nj + 1);
    for (const grid::Block& b : grid.blocks) {
      int col = 0;
      auto put = [&](double v) {
        std::fprintf(out, "%.17g%c", v, ++col % 5 == 0 ? '\n' : ' ');
      };
      for (int c = 0; c < 3; ++c) {
        for (const Eigen::Vector2d& p : b.nodes) put(c < 2 ? p[c] : z);
      }
      if (col % 5 != 0) std::fputc('\n', out);
    }
    if (std::ferror(out)) throw ExportError("write error on " + tmp.string());
  });
}

}  // namespace cg::io
