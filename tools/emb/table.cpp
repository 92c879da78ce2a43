#include "tools/emb/table.h"

#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <ostream>

namespace emb::cli {

Table::Table(std::string title, std::vector<std::string> keys, std::vector<std::string> headers)
    : title_(std::move(title)), keys_(std::move(keys)), headers_(std::move(headers)) {}

void Table::AddRow(std::vector<Cell> row) { rows_.push_back(std::move(row)); }

std::string Table::Format(const Cell& c) const {
  if (const auto* s = std::get_if<std::string>(&c)) return *s;
  if (const auto* i = std::get_if<long long>(&c)) return std::to_string(*i);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", precision_, std::get<double>(c));
  return buf;
}

void Table::Print(std::ostream& os) const {
  std::vector<size_t> width(headers_.size());
  for (size_t j = 0; j < headers_.size(); ++j) width[j] = headers_[j].size();
  for (const auto& r : rows_)
    for (size_t j = 0; j < r.size() && j < width.size(); ++j)
      width[j] = std::max(width[j], Format(r[j]).size());
  if (!title_.empty()) os << title_ << "\n";
  for (size_t j = 0; j < headers_.size(); ++j)
    os << (j ? "  " : "") << std::setw(static_cast<int>(width[j])) << headers_[j];
  os << "\n";
  for (const auto& r : rows_) {
    for (size_t j = 0; j < r.size() && j < width.size(); ++j)
      os << (j ? "  " : "") << std::setw(static_cast<int>(width[j])) << Format(r[j]);
    os << "\n";
  }
}

nlohmann::json Table::ToJson() const {
  nlohmann::json arr = nlohmann::json::array();
  for (const auto& r : rows_) {
    nlohmann::json o = nlohmann::json::object();
    for (size_t j = 0; j < r.size() && j < keys_.size(); ++j)
      std::visit([&](const auto& v) { o[keys_[j]] = v; }, r[j]);
    arr.push_back(o);
  }
  return arr;
}

void Summary::Add(const std::string& key, const std::string& label, nlohmann::json value) {
  items_.emplace_back(key, label, std::move(value));
}

void Summary::Print(std::ostream& os) const {
  size_t w = 0;
  for (const auto& it : items_) w = std::max(w, std::get<1>(it).size());
  if (!title_.empty()) os << title_ << "\n";
  for (const auto& [key, label, value] : items_) {
    os << "  " << std::left << std::setw(static_cast<int>(w)) << label << std::right << "  ";
    if (value.is_string())
      os << value.get<std::string>();
    else if (value.is_number_float()) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.6g", value.get<double>());
      os << buf;
    } else
      os << value.dump();
    os << "\n";
  }
}

nlohmann::json Summary::ToJson() const {
  nlohmann::json o = nlohmann::json::object();
  for (const auto& [key, label, value] : items_) o[key] = value;
  return o;
}

std::string FormatNumber(double value, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, value);
  return buf;
}

}  // namespace emb::cli
