#include "json_locations.hpp"

#include <nlohmann/json.hpp>

namespace hstmon::host::detail {

namespace {

class Walker {
 public:
  Walker(std::string_view text, int max_depth, JsonLocations& out)
      : s_(text), max_depth_(max_depth), out_(out) {}

  void run() {
    if (s_.substr(0, 3) == "\xEF\xBB\xBF") i_ = 3;  // offsets stay relative to the whole text
    ws();
    value("", 0);
  }

 private:
  void ws() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\n' || s_[i_] == '\r')) ++i_;
  }

  /// Skips a string starting at the opening quote; returns its raw text with quotes.
  std::string_view string_token() {
    const std::size_t start = i_;
    ++i_;
    while (i_ < s_.size() && s_[i_] != '"') {
      if (s_[i_] == '\\') ++i_;
      ++i_;
    }
    if (i_ < s_.size()) ++i_;
    return s_.substr(start, i_ - start);
  }

  static bool ends_literal(char c) noexcept {
    return c == ',' || c == '}' || c == ']' || c == ' ' || c == '\t' || c == '\n' || c == '\r';
  }

  /// Skips any value without recursion (strings, nested containers, literals).
  void skip_value() {
    if (i_ >= s_.size()) return;
    const char c0 = s_[i_];
    if (c0 == '"') {
      string_token();
      return;
    }
    if (c0 == '{' || c0 == '[') {
      std::size_t depth = 0;
      while (i_ < s_.size()) {
        const char c = s_[i_];
        if (c == '"') {
          string_token();
          continue;
        }
        if (c == '{' || c == '[') {
          ++depth;
        } else if ((c == '}' || c == ']') && --depth == 0) {
          ++i_;
          return;
        }
        ++i_;
      }
      return;
    }
    while (i_ < s_.size() && !ends_literal(s_[i_])) ++i_;
  }

  static std::string decode_key(std::string_view raw) {
    if (raw.find('\\') == std::string_view::npos) return std::string(raw.substr(1, raw.size() - 2));
    const nlohmann::json j = nlohmann::json::parse(raw, nullptr, false);
    return j.is_string() ? j.get<std::string>() : std::string(raw);
  }

  void value(const std::string& path, int depth) {
    if (i_ >= s_.size()) return;
    if (s_[i_] != '{' || depth >= max_depth_) {
      skip_value();
      return;
    }
    ++i_;  // '{'
    std::map<std::string, bool> seen;
    for (;;) {
      ws();
      if (i_ >= s_.size() || s_[i_] == '}') break;
      if (s_[i_] == ',') {
        ++i_;
        continue;
      }
      if (s_[i_] != '"') return;  // not valid JSON; nothing more to record
      const std::size_t key_pos = i_;
      const std::string key = decode_key(string_token());
      const std::string member = path + "/" + json_pointer_token(key);
      if (!seen.emplace(key, true).second && !out_.duplicate) out_.duplicate.emplace(member, key_pos);
      out_.key.emplace(member, key_pos);
      ws();
      if (i_ < s_.size() && s_[i_] == ':') ++i_;
      ws();
      out_.value.emplace(member, i_);
      value(member, depth + 1);
    }
    if (i_ < s_.size()) ++i_;  // '}'
  }

  std::string_view s_;
  std::size_t i_ = 0;
  int max_depth_;
  JsonLocations& out_;
};

}  // namespace

std::string json_pointer_token(std::string_view key) {
  std::string out;
  for (char c : key) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

JsonLocations locate_json_members(std::string_view text, int max_depth) {
  JsonLocations out;
  Walker w(text, max_depth, out);
  w.run();
  return out;
}

}  // namespace hstmon::host::detail
