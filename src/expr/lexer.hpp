#pragma once
// Tokens of the expression language, and where a parse error points.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace isopatch::expr {

enum class TokenKind {
  Number,
  Identifier,
  Symbol,     ///< one of + - * / ^ ( ) , =
  Separator,  ///< ';' or a newline that ends a statement
  End,
};

struct Token {
  TokenKind kind;
  std::string_view text;   ///< the characters of the token (empty for End)
  double number = 0.0;     ///< for Number
  std::size_t offset = 0;  ///< byte offset in the source; for End, just after the last token
};

/// Splits a formula into tokens. Comments (# to the end of the line) and blanks are dropped; a
/// newline becomes a Separator unless it is inside parentheses, follows an operator, '(' , ',' or
/// '=', or precedes a line starting with + - * / ^ or ')' (then the statement continues).
/// \throw ParseError on a character that starts no token or a number out of range
std::vector<Token> tokenize(std::string_view source);

/// Throws a ParseError pointing at byte `offset` of `source` (line, column and the line's text).
[[noreturn]] void throw_parse_error(std::string_view source, std::size_t offset, const std::string& reason);

/// How a token is named in messages: "'foo'", "number 2.5", "end of formula", ...
std::string describe(const Token& token);

}  // namespace isopatch::expr
