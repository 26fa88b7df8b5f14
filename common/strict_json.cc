#include "common/strict_json.h"

#include <iterator>
#include <utility>
#include <vector>

#include "common/error.h"
#include "common/json_reader.h"

namespace foresight {

namespace {

using Json = nlohmann::json;

// Builds the tree from nlohmann's SAX events (the interface of nlohmann::json_sax), with the
// strict checks. `open_` holds the containers not yet closed, innermost last; a value goes into
// the innermost one (an array's end, or the member its last key made).
class StrictBuilder {
 public:
  StrictBuilder(Json& root, const std::string& origin, std::size_t& events)
      : root_(root), origin_(origin), events_(events) {}

  bool null() { return Store(nullptr); }
  bool boolean(bool value) { return Store(value); }
  bool number_integer(Json::number_integer_t value) { return Store(value); }
  bool number_unsigned(Json::number_unsigned_t value) { return Store(value); }
  bool number_float(Json::number_float_t value, const Json::string_t&) { return Store(value); }
  bool string(Json::string_t& value) { return Store(std::move(value)); }
  bool binary(Json::binary_t& value) { return Store(std::move(value)); }

  bool start_object(std::size_t) { return Open(Json::value_t::object); }
  bool start_array(std::size_t) { return Open(Json::value_t::array); }
  bool end_object() { return Close(); }
  bool end_array() { return Close(); }

  bool key(Json::string_t& key) {
    ++events_;
    RequireDepth();
    auto& members = open_.back()->get_ref<Json::object_t&>();
    const auto [at, fresh] = members.try_emplace(std::move(key));
    if (!fresh) {
      throw InputError(origin_ + ": invalid JSON: the key " + QuoteJson(Json(at->first)) +
                       " appears twice in one object");
    }
    member_ = &at->second;
    return true;
  }

  // Syntax errors and overflowing numbers: thrown with their own type (parse_error carries the
  // byte offset), for ParseStrictJson to word.
  template <typename Exception>
  bool parse_error(std::size_t, const std::string&, const Exception& error) {
    throw error;
  }

 private:
  // nlohmann's callback parser counted depth as the containers open around a value or key;
  // the limit keeps that meaning.
  void RequireDepth() const {
    if (open_.size() > static_cast<std::size_t>(kMaxJsonDepth)) {
      throw InputError(origin_ + ": invalid JSON: nested deeper than " +
                       std::to_string(kMaxJsonDepth) + " levels");
    }
  }

  // Puts `value` where the next value goes and returns where it now is.
  template <typename Value>
  Json* Place(Value&& value) {
    ++events_;
    RequireDepth();
    if (open_.empty()) {
      root_ = Json(std::forward<Value>(value));
      return &root_;
    }
    Json& parent = *open_.back();
    if (parent.is_array()) {
      auto& items = parent.get_ref<Json::array_t&>();
      items.emplace_back(std::forward<Value>(value));
      return &items.back();
    }
    *member_ = Json(std::forward<Value>(value));
    return member_;
  }

  template <typename Value>
  bool Store(Value&& value) {
    Place(std::forward<Value>(value));
    return true;
  }

  bool Open(Json::value_t kind) {
    open_.push_back(Place(kind));
    return true;
  }

  bool Close() {
    ++events_;
    open_.pop_back();
    return true;
  }

  Json& root_;
  const std::string& origin_;
  std::size_t& events_;
  std::vector<Json*> open_;
  Json* member_ = nullptr;
};

// A character iterator that counts how far it was advanced (JsonParseWork::characters_read).
class CountingIterator {
 public:
  using iterator_category = std::forward_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  CountingIterator(const char* at, std::size_t* count) : at_(at), count_(count) {}
  reference operator*() const { return *at_; }
  CountingIterator& operator++() {
    ++at_;
    ++*count_;
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator before = *this;
    ++*this;
    return before;
  }
  bool operator==(const CountingIterator& other) const { return at_ == other.at_; }
  bool operator!=(const CountingIterator& other) const { return at_ != other.at_; }

 private:
  const char* at_;
  std::size_t* count_;
};

// nlohmann reports a byte offset; people want line and column.
std::string LineAndColumn(std::string_view text, std::size_t byte) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i + 1 < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// ", field \"x_m\"" when the text just before `at` is `"x_m":`, else "".
std::string KeyBefore(std::string_view text, std::size_t at) {
  const auto colon = text.rfind(':', at);
  if (colon == std::string_view::npos) return "";
  const auto close = text.rfind('"', colon);
  if (close == std::string_view::npos || close == 0) return "";
  const auto open = text.rfind('"', close - 1);
  if (open == std::string_view::npos) return "";
  return ", field \"" + std::string(text.substr(open + 1, close - open - 1)) + "\"";
}

// nlohmann quotes everything its lexer read of the failing token ("last read: '...'"), which
// for a file that is no JSON (an image, a log) is its first bytes, up to the whole file: the
// message keeps the last kMaxQuotedBytes of it, where the error is (line and column say where).
constexpr std::size_t kMaxQuotedBytes = 40;

std::string CutLastRead(std::string what) {
  const std::string marker = "; last read: '";
  const auto open = what.find(marker);
  if (open == std::string::npos) return what;
  const auto start = open + marker.size();
  const auto close = what.rfind('\'');
  if (close == std::string::npos || close < start || close - start <= kMaxQuotedBytes) return what;
  auto from = close - kMaxQuotedBytes;
  // Not inside a UTF-8 sequence: skip its continuation bytes.
  while (from < close && (static_cast<unsigned char>(what[from]) & 0xC0) == 0x80) ++from;
  return what.substr(0, start) + "..." + what.substr(from);
}

// "syntax error while parsing value - invalid literal; last read: 'x'" without the prefix.
std::string ParseProblem(const Json::parse_error& e) {
  std::string what = e.what();
  auto colon = what.find(": ", what.find("parse error"));
  return CutLastRead(colon == std::string::npos ? what : what.substr(colon + 2));
}

// nlohmann's other exceptions, e.g. out_of_range.406 "number overflow parsing '1e999'", located
// by the quoted token.
std::string OtherProblem(std::string_view text, const Json::exception& e) {
  std::string what = e.what();
  const auto bracket = what.find("] ");
  if (bracket != std::string::npos) what = what.substr(bracket + 2);
  std::string where;
  const auto open = what.find('\''), close = what.rfind('\'');
  if (open != std::string::npos && close > open) {
    const auto at = text.find(what.substr(open + 1, close - open - 1));
    if (at != std::string_view::npos)
      where = " at " + LineAndColumn(text, at + 2) + KeyBefore(text, at);
  }
  return where + ": " + what;
}

}  // namespace

nlohmann::json ParseStrictJson(std::string_view text, const std::string& origin,
                               JsonParseWork* work) {
  if (const auto nul = text.find('\0'); nul != std::string_view::npos) {
    throw InputError(origin + ": invalid JSON at " + LineAndColumn(text, nul + 1) +
                     ": a NUL byte (not a text file?)");
  }
  Json tree;
  std::size_t events = 0;
  StrictBuilder builder(tree, origin, events);
  try {
    if (work == nullptr) {
      Json::sax_parse(text.data(), text.data() + text.size(), &builder);
    } else {
      work->characters_read = 0;
      Json::sax_parse(CountingIterator(text.data(), &work->characters_read),
                      CountingIterator(text.data() + text.size(), &work->characters_read),
                      &builder);
      work->handler_events = events;
    }
  } catch (const Json::parse_error& e) {
    throw InputError(origin + ": invalid JSON at " + LineAndColumn(text, e.byte) + ": " +
                     ParseProblem(e));
  } catch (const Json::exception& e) {
    throw InputError(origin + ": invalid JSON" + OtherProblem(text, e));
  }
  return tree;
}

}  // namespace foresight
