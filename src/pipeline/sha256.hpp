#pragma once
// SHA-256 of everything a build read, for the input hash of report.json: a fingerprint so two runs can
// be compared without diffing configs and point files. A thin wrapper over OpenSSL's EVP digest
// (libcrypto), not an own implementation.
#include <memory>
#include <string>

struct evp_md_ctx_st;

namespace cg::pipeline {

class Sha256 {
 public:
  Sha256();
  ~Sha256();
  Sha256(const Sha256&) = delete;
  Sha256& operator=(const Sha256&) = delete;
  void update(const void* data, std::size_t size);
  void update(const std::string& s) { update(s.data(), s.size()); }
  /// The digest as 64 lower-case hex digits; the object is finished afterwards (no more update()).
  std::string hex_digest();

 private:
  evp_md_ctx_st* ctx_;
};

}  // namespace cg::pipeline
