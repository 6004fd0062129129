#include "src/config/json_document.hpp"

#include <set>
#include <vector>

#include "src/config/config_error.hpp"

namespace cg::config {
namespace {

using nlohmann::json;

// 1-based line and column of byte offset `pos` (the parser reports the offset after the offending
// character).
std::string line_column(const std::string& text, std::size_t pos) {
  pos = std::min(pos, text.size());
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i + 1 < pos; ++i) {
    if (text[i] == '\n') ++line, column = 1;
    else ++column;
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// The library's message without its exception id and its own position prefix:
// "[json.exception.parse_error.101] parse error at line 1, column 5: syntax error ..." -> "syntax error ...".
std::string plain_message(const std::string& what) {
  std::string s = what;
  if (s.rfind("[json.exception.", 0) == 0) {
    const auto close = s.find("] ");
    if (close != std::string::npos) s = s.substr(close + 2);
  }
  for (const char* prefix : {"parse error at ", "parse error: "})
    if (s.rfind(prefix, 0) == 0) {
      const auto colon = s.find(": ");
      if (colon != std::string::npos) s = s.substr(colon + 2);
    }
  return s;
}

// Builds the document like the library's own DOM parser and records the first problem.
class StrictDocument : public nlohmann::json_sax<json> {
 public:
  static constexpr std::size_t kMaxDepth = 64;
  json root;
  std::string error;  // empty while fine

  bool null() override { return add(json(nullptr)); }
  bool boolean(bool v) override { return add(json(v)); }
  bool number_integer(number_integer_t v) override { return add(json(v)); }
  bool number_unsigned(number_unsigned_t v) override { return add(json(v)); }
  bool number_float(number_float_t v, const string_t&) override { return add(json(v)); }
  bool string(string_t& v) override { return add(json(std::move(v))); }
  bool binary(binary_t& v) override { return add(json::binary(std::move(v))); }
  bool start_object(std::size_t) override { return open(json::object()); }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(json::array()); }
  bool end_array() override { return close(); }

  bool key(string_t& k) override {
    Frame& f = frames_.back();
    if (!f.keys.insert(k).second) {
      error = child_path(k) + ": duplicate key (given twice in the same object; JSON readers would silently keep "
                              "only one of the values): remove one";
      return false;
    }
    f.key = k;
    return true;
  }

  bool parse_error(std::size_t position, const std::string& last_token, const nlohmann::detail::exception& ex) override {
    // `position` is just past the offending character; a number's token text is reliable, so an
    // out-of-range number is pointed at by its first digit.
    position_ = ex.id == 406 && position > last_token.size() ? position - last_token.size() + 1 : position;
    if (ex.id == 406)  // out_of_range.406: number overflow
      error = "number out of range (" + plain_message(ex.what()) + "); numbers must be finite, at most ~1.8e308 in magnitude";
    else
      error = plain_message(ex.what());
    positioned_ = true;
    return false;
  }

  bool positioned() const { return positioned_; }
  bool too_deep() const { return too_deep_; }
  std::size_t position() const { return position_; }

 private:
  struct Frame {
    json* node;
    std::set<std::string> keys;  // objects: keys seen so far
    std::string key;             // objects: key of the value being read
  };

  // Path of the current container, in config::Field's notation (sections[2].points.file).
  std::string path() const {
    std::string p;
    for (std::size_t i = 0; i + 1 < frames_.size(); ++i) {
      const Frame& f = frames_[i];
      if (f.node->is_object()) p += (p.empty() ? "" : ".") + f.key;
      else p += "[" + std::to_string(f.node->size() - 1) + "]";  // the element being read is the last
    }
    return p;
  }
  // The member of the root being read ("sections"), or "the document" for the root itself.
  std::string top_level_path() const {
    if (frames_.size() < 2) return "the document";
    return frames_[0].node->is_object() ? frames_[0].key : "[" + std::to_string(frames_[0].node->size() - 1) + "]";
  }
  std::string child_path(const std::string& k) const {
    const std::string p = path();
    return p.empty() ? k : p + "." + k;
  }

  json* insert(json&& v) {
    if (frames_.empty()) {
      root = std::move(v);
      return &root;
    }
    Frame& f = frames_.back();
    if (f.node->is_object()) {
      json& slot = (*f.node)[f.key];
      slot = std::move(v);
      return &slot;
    }
    f.node->push_back(std::move(v));
    return &f.node->back();
  }
  bool add(json&& v) {
    insert(std::move(v));
    return true;
  }
  // A container stays at a fixed address while it is filled: its parent gets no other child meanwhile
  // (array elements are appended only after the previous one is closed).
  // Nesting is limited: copying, printing and destroying a document recurse once per level, so a
  // file of a million '[' would overflow the stack.
  bool open(json&& container) {
    if (frames_.size() >= kMaxDepth) {
      too_deep_ = true;
      error = "objects and arrays nested more than " + std::to_string(kMaxDepth) + " levels deep (in " +
              top_level_path() + "; the examples nest at most 6 levels)";
      return false;
    }
    frames_.push_back({insert(std::move(container)), {}, {}});
    return true;
  }
  bool close() {
    frames_.pop_back();
    return true;
  }

  std::vector<Frame> frames_;
  std::size_t position_ = 0;
  bool positioned_ = false;
  bool too_deep_ = false;
};

}  // namespace

json parse_json_document(const std::string& text, const std::string& source_name) {
  StrictDocument doc;
  const bool ok = json::sax_parse(text, &doc, json::input_format_t::json, /*strict=*/true);
  if (ok && doc.error.empty()) return std::move(doc.root);
  if (doc.error.empty()) doc.error = "invalid JSON";
  if (doc.positioned())
    throw ConfigError(source_name + " " + line_column(text, doc.position()) + ": " + doc.error);
  if (doc.too_deep()) throw ConfigError(source_name + ": " + doc.error);
  throw ConfigError(doc.error);
}

}  // namespace cg::config
