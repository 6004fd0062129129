#pragma once
// SHA-256 (FIPS 180-4), for the input hash of report.json: a fingerprint of everything a build read,
// so two runs can be compared without diffing configs and point files.
#include <array>
#include <cstdint>
#include <string>

namespace cg::pipeline {

class Sha256 {
 public:
  Sha256();
  void update(const void* data, std::size_t size);
  void update(const std::string& s) { update(s.data(), s.size()); }
  /// The digest as 64 lower-case hex digits; the object is finished afterwards (no more update()).
  std::string hex_digest();

 private:
  void block(const std::uint8_t* p);
  std::array<std::uint32_t, 8> h_;
  std::array<std::uint8_t, 64> buf_{};
  std::size_t buffered_ = 0;
  std::uint64_t length_ = 0;  // bytes
};

}  // namespace cg::pipeline
