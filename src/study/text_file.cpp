#include "src/study/text_file.hpp"

#include <fstream>
#include <sstream>

#include "export/atomic_file.hpp"

namespace cg::study {

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return in ? s.str() : std::string();
}

void write_text(const std::filesystem::path& target, const std::string& text) {
  io::write_atomically(target, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    if (!out) throw io::ExportError("cannot write " + target.string());
  });
}

}  // namespace cg::study
