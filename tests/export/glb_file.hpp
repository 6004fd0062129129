#pragma once
// A reader of the glTF 2.0 binary container for tests (the Khronos spec, "GLB File Format
// Specification"): the 12-byte header, the JSON chunk parsed, the BIN chunk's size, and each
// primitive's POSITION bounds (accessor min/max). Throws std::runtime_error on a malformed file.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace cg::test {

struct GlbFile {
  std::uint32_t version = 0;
  std::uint32_t length = 0;  ///< as the header says
  nlohmann::json gltf;
  std::size_t bin_bytes = 0;
};

inline GlbFile read_glb(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string b = ss.str();
  const auto u32 = [&](std::size_t at) {
    if (at + 4 > b.size()) throw std::runtime_error("glb: truncated at byte " + std::to_string(at));
    std::uint32_t v;
    std::memcpy(&v, b.data() + at, 4);  // little-endian on the test machines
    return v;
  };
  if (b.compare(0, 4, "glTF") != 0) throw std::runtime_error("glb: no glTF magic");
  GlbFile g;
  g.version = u32(4);
  g.length = u32(8);
  const std::uint32_t json_length = u32(12);
  if (b.compare(16, 4, "JSON") != 0 || 20 + json_length > b.size()) throw std::runtime_error("glb: bad JSON chunk");
  g.gltf = nlohmann::json::parse(b.substr(20, json_length));
  const std::size_t bin = 20 + json_length;
  if (bin + 8 <= b.size() && b.compare(bin + 4, 4, std::string("BIN\0", 4)) == 0) g.bin_bytes = u32(bin);
  return g;
}

}  // namespace cg::test
