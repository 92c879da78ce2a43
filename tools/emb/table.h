#pragma once
/// @file
/// A table the CLI prints either as aligned text or as JSON (--json): one source for both.

#include <iosfwd>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

namespace emb::cli {

class Table {
 public:
  using Cell = std::variant<std::string, double, long long>;
  /// `keys` name the JSON fields; `headers` the text columns (same count).
  Table(std::string title, std::vector<std::string> keys, std::vector<std::string> headers);

  /// Adds a row (one cell per column). Doubles print with `precision` significant digits.
  void AddRow(std::vector<Cell> row);
  void set_precision(int p) { precision_ = p; }

  /// Aligned text with the title and a header line.
  void Print(std::ostream& os) const;
  /// An array of objects {key: value}.
  nlohmann::json ToJson() const;

 private:
  std::string Format(const Cell& c) const;
  std::string title_;
  std::vector<std::string> keys_, headers_;
  std::vector<std::vector<Cell>> rows_;
  int precision_{8};
};

/// Key/value pairs printed as "key: value" lines or a JSON object.
class Summary {
 public:
  explicit Summary(std::string title) : title_(std::move(title)) {}
  void Add(const std::string& key, const std::string& label, nlohmann::json value);
  void Print(std::ostream& os) const;
  nlohmann::json ToJson() const;

 private:
  std::string title_;
  std::vector<std::tuple<std::string, std::string, nlohmann::json>> items_;
};

/// A number for a message with its significant digits ("4.6e-10", "0.35", "3000"), never
/// std::to_string's fixed six decimals ("0.000000").
std::string FormatNumber(double value, int digits = 3);

}  // namespace emb::cli
