// The tokenizer and the placement of parse errors.
#include "expr/lexer.hpp"

#include <isopatch/expression.hpp>

#include <cctype>
#include <charconv>
#include <cmath>
#include <string>

namespace isopatch::expr {
namespace {

bool is_ident_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool is_ident_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}
bool is_digit(char c) {
  return c >= '0' && c <= '9';
}
/// 'text' in quotes (appending avoids GCC 12's false -Wrestrict on short string concatenations).
std::string quoted(std::string_view text) {
  std::string q;
  q.reserve(text.size() + 2);
  q += '\'';
  q.append(text);
  q += '\'';
  return q;
}

bool is_operator(char c) {
  return c == '+' || c == '-' || c == '*' || c == '/' || c == '^';
}

class Lexer {
 public:
  explicit Lexer(std::string_view s) : s_(s) {}

  std::vector<Token> run() {
    while (i_ < s_.size()) {
      const char c = s_[i_];
      if (c == '#') {
        skip_comment();
      } else if (c == '\n') {
        newline();
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        ++i_;
      } else if (is_digit(c) || (c == '.' && i_ + 1 < s_.size() && is_digit(s_[i_ + 1]))) {
        number();
      } else if (is_ident_start(c)) {
        std::size_t j = i_ + 1;
        while (j < s_.size() && is_ident_char(s_[j])) ++j;
        push(TokenKind::Identifier, j);
      } else if (c == ';') {
        push(TokenKind::Separator, i_ + 1);
      } else if (is_operator(c) || c == '(' || c == ')' || c == ',' || c == '=') {
        depth_ += c == '(' ? 1 : (c == ')' && depth_ > 0 ? -1 : 0);
        push(TokenKind::Symbol, i_ + 1);
      } else {
        throw_parse_error(s_, i_, "unexpected character " + quoted(std::string_view(&c, 1)));
      }
    }
    tokens_.push_back(Token{TokenKind::End, {}, 0.0, end_});
    return std::move(tokens_);
  }

 private:
  void push(TokenKind kind, std::size_t end, double number = 0.0) {
    tokens_.push_back(Token{kind, s_.substr(i_, end - i_), number, i_});
    i_ = end;
    end_ = end;
  }

  void skip_comment() {
    while (i_ < s_.size() && s_[i_] != '\n') ++i_;
  }

  void number() {
    std::size_t j = i_;
    while (j < s_.size() && is_digit(s_[j])) ++j;
    if (j < s_.size() && s_[j] == '.') {
      ++j;
      while (j < s_.size() && is_digit(s_[j])) ++j;
    }
    // An exponent only when digits follow: "2e" is the number 2 and the name e.
    if (j < s_.size() && (s_[j] == 'e' || s_[j] == 'E')) {
      std::size_t k = j + 1;
      if (k < s_.size() && (s_[k] == '+' || s_[k] == '-')) ++k;
      if (k < s_.size() && is_digit(s_[k])) {
        j = k;
        while (j < s_.size() && is_digit(s_[j])) ++j;
      }
    }
    double value = 0.0;
    const auto [ptr, ec] = std::from_chars(s_.data() + i_, s_.data() + j, value);
    if (ec != std::errc() || ptr != s_.data() + j || !std::isfinite(value))
      throw_parse_error(s_, i_, "number " + quoted(s_.substr(i_, j - i_)) + " is out of range");
    push(TokenKind::Number, j, value);
  }

  void newline() {
    const std::size_t at = i_;
    ++i_;
    if (depth_ > 0 || tokens_.empty()) return;
    const Token& last = tokens_.back();
    if (last.kind == TokenKind::Separator) return;
    if (last.kind == TokenKind::Symbol && last.text != ")") return;  // after an operator, '(' ',' '='
    // Look at the next significant character: a leading operator continues the statement.
    std::size_t j = i_;
    while (j < s_.size()) {
      if (s_[j] == '#') {
        while (j < s_.size() && s_[j] != '\n') ++j;
      } else if (std::isspace(static_cast<unsigned char>(s_[j]))) {
        ++j;
      } else {
        break;
      }
    }
    if (j < s_.size() && (is_operator(s_[j]) || s_[j] == ')')) return;
    tokens_.push_back(Token{TokenKind::Separator, s_.substr(at, 1), 0.0, at});
  }

  std::string_view s_;
  std::size_t i_ = 0;
  std::size_t end_ = 0;
  int depth_ = 0;
  std::vector<Token> tokens_;
};

}  // namespace

std::vector<Token> tokenize(std::string_view source) {
  return Lexer(source).run();
}

void throw_parse_error(std::string_view source, std::size_t offset, const std::string& reason) {
  if (offset > source.size()) offset = source.size();
  std::size_t begin = 0;
  if (offset > 0) {
    const std::size_t newline = source.rfind('\n', offset - 1);
    begin = newline == std::string_view::npos ? 0 : newline + 1;
  }
  std::size_t end = source.find('\n', begin);
  if (end == std::string_view::npos) end = source.size();
  int line = 1;
  for (std::size_t k = 0; k < begin; ++k) line += source[k] == '\n' ? 1 : 0;
  std::string text(source.substr(begin, end - begin));
  if (!text.empty() && text.back() == '\r') text.pop_back();
  throw ParseError(reason, std::move(text), line, static_cast<int>(offset - begin) + 1);
}

std::string describe(const Token& token) {
  switch (token.kind) {
    case TokenKind::Number:
      return "number " + std::string(token.text);
    case TokenKind::Identifier:
    case TokenKind::Symbol:
      return quoted(token.text);
    case TokenKind::Separator:
      return token.text == ";" ? "';'" : "end of line";
    case TokenKind::End:
      return "end of formula";
  }
  return "?";
}

}  // namespace isopatch::expr
