#include "libemb/mesh/geo_lexer.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "libemb/common/error.h"

namespace emb {
namespace {

bool IsDigit(char c) { return c >= '0' && c <= '9'; }
bool IsAlpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }

// The multi-character symbols of Gmsh.l, longest first where one is a prefix of another.
constexpr std::array<std::string_view, 16> kSymbols = {
    "...", "::", "+=", "-=", "*=", "/=", "||", "&&", "++", "--", "==", "!=", "<=", ">=", ">>", "<<"};

// Length of the exponent [Ee][-+]?[0-9]+ at `i`, 0 if there is none.
std::size_t ExponentLength(std::string_view t, std::size_t i) {
  if (i >= t.size() || (t[i] != 'e' && t[i] != 'E')) return 0;
  std::size_t j = i + 1;
  if (j < t.size() && (t[j] == '+' || t[j] == '-')) ++j;
  const std::size_t digits_start = j;
  while (j < t.size() && IsDigit(t[j])) ++j;
  return j > digits_start ? j - i : 0;
}

// Length of the number literal at `i` (flex's longest match over Gmsh.l's number rules), 0 if
// none starts there.
std::size_t NumberLength(std::string_view t, std::size_t i) {
  std::size_t j = i;
  while (j < t.size() && IsDigit(t[j])) ++j;
  const bool int_part = j > i;
  if (j < t.size() && t[j] == '.') {
    std::size_t k = j + 1;
    while (k < t.size() && IsDigit(t[k])) ++k;
    if (int_part || k > j + 1) j = k;  // "1.", "1.5" or ".5"; a lone "." is a symbol
  }
  if (j == i) return 0;
  return j - i + ExponentLength(t, j);
}

}  // namespace

std::vector<GeoToken> LexGeoScript(std::string_view t, const std::string& source) {
  std::vector<GeoToken> tokens;
  int line = 1;
  std::size_t i = 0;
  const std::size_t n = t.size();
  auto advance_to = [&](std::size_t j) {  // moves to j, counting the line breaks passed
    for (; i < j; ++i)
      if (t[i] == '\n') ++line;
  };
  while (i < n) {
    const char c = t[i];
    if (c == '\0')
      EMB_THROW(InputError, source << ":" << line
                                   << ": NUL byte: gmsh's lexer stops a comment or string there and "
                                      "reads the rest as script; expected a text file");
    if (IsSpace(c)) {
      advance_to(i + 1);
      continue;
    }
    if (c == '/' && i + 1 < n && t[i + 1] == '/') {
      std::size_t j = i + 2;
      while (j < n && t[j] != '\n' && t[j] != '\0') ++j;
      advance_to(j);
      continue;
    }
    if (c == '/' && i + 1 < n && t[i + 1] == '*') {
      std::size_t j = i + 2;
      while (j < n && !(t[j] == '*' && j + 1 < n && t[j + 1] == '/') && t[j] != '\0') ++j;
      advance_to(j < n && t[j] == '*' ? j + 2 : j);
      continue;
    }
    if (c == '"' || c == '\'') {
      const int start_line = line;
      std::size_t j = i + 1;
      while (j < n && t[j] != c && t[j] != '\0') ++j;
      EMB_THROW_IF(j - i - 1 > kGmshMaxStringLength,
                   source << ":" << start_line << ": string of " << (j - i - 1)
                          << " characters: gmsh keeps " << kGmshMaxStringLength
                          << " and reads the rest as script; expected a shorter string");
      tokens.push_back({GeoToken::Kind::kString, std::string(t.substr(i + 1, j - i - 1)),
                        start_line});
      advance_to(j < n && t[j] == c ? j + 1 : j);
      continue;
    }
    if (IsAlpha(c)) {
      std::size_t j = i + 1;
      while (j < n && (IsAlpha(t[j]) || IsDigit(t[j]))) ++j;
      tokens.push_back({GeoToken::Kind::kName, std::string(t.substr(i, j - i)), line});
      i = j;
      continue;
    }
    if (const std::size_t len = NumberLength(t, i); len > 0) {
      tokens.push_back({GeoToken::Kind::kNumber, std::string(t.substr(i, len)), line});
      i += len;
      continue;
    }
    std::size_t len = 1;
    for (std::string_view s : kSymbols)
      if (t.substr(i, s.size()) == s) {
        len = s.size();
        break;
      }
    tokens.push_back({GeoToken::Kind::kSymbol, std::string(t.substr(i, len)), line});
    i += len;
  }
  return tokens;
}

std::vector<std::pair<std::string, double>> DefineConstantParameters(
    const std::vector<GeoToken>& tokens) {
  std::vector<std::pair<std::string, double>> out;
  const std::size_t n = tokens.size();
  auto is = [&](std::size_t k, const char* symbol) {
    return k < n && tokens[k].kind == GeoToken::Kind::kSymbol && tokens[k].text == symbol;
  };
  auto opens = [&](std::size_t k) { return is(k, "[") || is(k, "{") || is(k, "("); };
  auto closes = [&](std::size_t k) { return is(k, "]") || is(k, "}") || is(k, ")"); };
  for (std::size_t k = 0; k + 1 < n; ++k) {
    if (tokens[k].kind != GeoToken::Kind::kName || tokens[k].text != "DefineConstant" ||
        !is(k + 1, "["))
      continue;
    std::size_t p = k + 2;
    // Entries `name = value` or `name = {value, attributes...}`, separated by commas at the
    // block's own depth, up to the closing bracket.
    while (p < n && !is(p, "]")) {
      if (tokens[p].kind == GeoToken::Kind::kName && is(p + 1, "=")) {
        const std::string name = tokens[p].text;
        std::size_t v = p + 2;
        const bool braced = is(v, "{");
        if (braced) ++v;
        // The default value: the tokens up to the next comma or closing bracket at depth 0.
        std::size_t e = v;
        int depth = 0;
        while (e < n && !(depth == 0 && (is(e, ",") || closes(e)))) {
          if (opens(e)) ++depth;
          if (closes(e)) --depth;
          ++e;
        }
        const std::size_t count = e - v;
        const bool is_string = count >= 1 && tokens[v].kind == GeoToken::Kind::kString;
        if (!is_string && count > 0) {
          double value = std::numeric_limits<double>::quiet_NaN();
          const bool sign = count == 2 && (is(v, "-") || is(v, "+"));
          const std::size_t num = sign ? v + 1 : v;
          if ((count == 1 || sign) && tokens[num].kind == GeoToken::Kind::kNumber) {
            value = std::strtod(tokens[num].text.c_str(), nullptr);
            if (is(v, "-")) value = -value;
          }
          out.emplace_back(name, value);
        }
        p = e;
        if (braced) {  // skip the attributes up to the entry's closing brace
          depth = 0;
          while (p < n && !(depth == 0 && is(p, "}"))) {
            if (opens(p)) ++depth;
            if (closes(p)) --depth;
            if (depth < 0) break;
            ++p;
          }
          if (is(p, "}")) ++p;
        }
      }
      // On to the next entry: past the comma at the block's depth.
      int depth = 0;
      while (p < n && !(depth == 0 && (is(p, ",") || is(p, "]")))) {
        if (opens(p)) ++depth;
        if (closes(p)) --depth;
        if (depth < 0) break;
        ++p;
      }
      if (is(p, ",")) ++p;
      if (p < n && closes(p) && !is(p, "]")) break;  // malformed: stop at a stray bracket
    }
    k = p;
  }
  return out;
}

}  // namespace emb
