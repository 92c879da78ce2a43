#pragma once
/// @file
/// The tokens of gmsh's .geo language, cut exactly where gmsh 4.8's own lexer
/// (Parser/Gmsh.l) cuts them, so that what a check sees is what gmsh would execute: comments
/// `//` to the end of the line (`\n` only) and `/* … */` (not nested), strings in double or
/// single quotes with no escapes, names [A-Za-z_][A-Za-z0-9_]*, numbers, and symbols.
/// Used to read a file's `DefineConstant` parameters and to audit a script before gmsh runs it
/// (gmsh_input_audit.h). Linear in the text, no recursion, no regular expressions.

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace emb {

/// One token of a .geo script.
struct GeoToken {
  enum class Kind {
    kName,    ///< a name: keyword, command, variable or option category
    kNumber,  ///< a number literal, e.g. 1, 2.5e-3, .5
    kString,  ///< a quoted string; `text` is its content without the quotes
    kSymbol,  ///< punctuation or an operator: ";", "(", ">>", "::", ...
  };
  Kind kind;
  std::string text;
  int line;  ///< 1-based line where the token starts
};

/// gmsh 4.8 keeps at most this many characters of a string (`parsestring` in Gmsh.l) and
/// reads the rest of a longer string as script.
inline constexpr std::size_t kGmshMaxStringLength = 1023;

/// Cuts `text` into tokens as gmsh 4.8 does. An unterminated comment or string ends at the end
/// of the text (gmsh reports an error there; nothing can hide behind it).
/// @throws InputError naming `source` and the line for text that gmsh would cut differently
///         from what it shows: a NUL byte (gmsh's lexer stops a comment or string there and
///         reads on as script) or a string longer than kGmshMaxStringLength characters.
std::vector<GeoToken> LexGeoScript(std::string_view text, const std::string& source);

/// The parameters a script declares in `DefineConstant[ name = value, name = {value, ...},
/// ... ];` blocks, in order, with their default values; NaN when the default is an
/// expression rather than a (signed) number. String constants are skipped. Tolerates
/// malformed blocks (reads what it can). Cost O(tokens).
std::vector<std::pair<std::string, double>> DefineConstantParameters(
    const std::vector<GeoToken>& tokens);

}  // namespace emb
