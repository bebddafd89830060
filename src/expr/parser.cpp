// Recursive descent, one function per precedence level:
//   program    := { statement (';' | newline) }      the last statement is f, the others definitions
//   statement  := name '=' expression | expression
//   expression := term { ('+' | '-') term }
//   term       := unary { ('*' | '/') unary }
//   unary      := ('-' | '+') unary | power           so -x^2 = -(x^2)
//   power      := primary [ '^' unary ]               right-associative: 2^3^2 = 2^9
//   primary    := number | name | name '(' arguments ')' | '(' expression ')'
// Nodes go straight into the DAG, which shares and folds as they are made.
#include "expr/parser.hpp"

#include "expr/lexer.hpp"
#include "expr/suggest.hpp"

#include <isopatch/error.hpp>

#include <numbers>
#include <set>
#include <vector>

namespace isopatch::expr {
namespace {

constexpr int kMaxDepth = 500;

const std::vector<std::string> kBuiltinNames = {"x", "y", "z", "pi", "e"};

class Parser {
 public:
  Parser(std::string_view source, const std::map<std::string, double>& params, Dag& dag)
      : source_(source), tokens_(tokenize(source)), params_(params), dag_(dag) {}

  NodeId program() {
    NodeId result = -1;
    for (;;) {
      while (peek().kind == TokenKind::Separator) ++pos_;
      if (peek().kind == TokenKind::End) break;
      const bool definition = peek().kind == TokenKind::Identifier && peek(1).text == "=";
      if (result >= 0)
        fail(peek(), definition
                         ? "definitions must come before the expression of f"
                         : "only the last statement may be an expression (write 'name = ...' to define)");
      if (definition) {
        define();
      } else {
        result = expression();
      }
      end_of_statement();
    }
    if (result < 0)
      fail(peek(), tokens_.size() == 1 ? "empty formula" : "the formula ends without an expression for f");
    check_params();
    return result;
  }

 private:
  const Token& peek(std::size_t ahead = 0) const {
    return tokens_[std::min(pos_ + ahead, tokens_.size() - 1)];
  }
  const Token& next() {
    const Token& t = tokens_[pos_];
    if (pos_ + 1 < tokens_.size()) ++pos_;
    return t;
  }
  bool at(std::string_view symbol) const { return peek().kind == TokenKind::Symbol && peek().text == symbol; }

  [[noreturn]] void fail(const Token& at_token, const std::string& reason) const {
    throw_parse_error(source_, at_token.offset, reason);
  }

  int column_of(std::size_t offset) const {
    const std::size_t newline = offset == 0 ? std::string_view::npos : source_.rfind('\n', offset - 1);
    return static_cast<int>(newline == std::string_view::npos ? offset : offset - newline - 1) + 1;
  }

  void end_of_statement() {
    const Token& t = peek();
    if (t.kind == TokenKind::Separator || t.kind == TokenKind::End) return;
    if (t.text == ")") fail(t, "unmatched ')'");
    if (t.text == "=") fail(t, "'=' must follow a single name at the start of a statement");
    fail(t, "expected an operator before " + describe(t));
  }

  void define() {
    const Token& name_token = next();
    const std::string name(name_token.text);
    if (name == "x" || name == "y" || name == "z")
      fail(name_token, "'" + name + "' is a variable and cannot be defined");
    if (name == "pi" || name == "e")
      fail(name_token, "'" + name + "' is a built-in constant and cannot be redefined");
    if (find_function(name)) fail(name_token, "'" + name + "' is a function and cannot be defined");
    if (definitions_.count(name)) fail(name_token, "'" + name + "' is already defined");
    next();  // '='
    defining_ = name;
    defining_offset_ = name_token.offset;
    NodeId value = expression();
    defining_.clear();
    if (const auto it = params_.find(name); it != params_.end()) {
      value = dag_.constant(it->second);
      used_params_.insert(name);
    }
    definitions_.emplace(name, value);
    definition_order_.push_back(name);
  }

  NodeId expression() {
    NodeId left = term();
    while (at("+") || at("-")) {
      const Op op = next().text == "+" ? Op::Add : Op::Sub;
      left = dag_.binary(op, left, term());
    }
    return left;
  }

  NodeId term() {
    NodeId left = unary();
    while (at("*") || at("/")) {
      const Op op = next().text == "*" ? Op::Mul : Op::Div;
      left = dag_.binary(op, left, unary());
    }
    return left;
  }

  NodeId unary() {
    if (++depth_ > kMaxDepth) fail(peek(), "the formula is nested too deeply");
    NodeId result;
    if (at("-")) {
      next();
      result = dag_.unary(Op::Neg, unary());
    } else if (at("+")) {
      next();
      result = unary();
    } else {
      result = power();
    }
    --depth_;
    return result;
  }

  NodeId power() {
    const NodeId base = primary();
    if (!at("^")) return base;
    next();
    return dag_.binary(Op::Pow, base, unary());
  }

  NodeId primary() {
    const Token& t = next();
    switch (t.kind) {
      case TokenKind::Number:
        return dag_.constant(t.number);
      case TokenKind::Identifier:
        return at("(") ? call(t) : name(t);
      case TokenKind::Symbol:
        if (t.text == "(") {
          const NodeId inside = expression();
          if (!at(")"))
            fail(peek(), "expected ')' to close the '(' at column " + std::to_string(column_of(t.offset)) +
                             ", found " + describe(peek()));
          next();
          return inside;
        }
        break;
      default:
        break;
    }
    fail(t, "expected a number, a name or '(' but found " + describe(t));
  }

  NodeId name(const Token& t) {
    const std::string n(t.text);
    if (n == "x") return dag_.variable(0);
    if (n == "y") return dag_.variable(1);
    if (n == "z") return dag_.variable(2);
    if (n == "pi") return dag_.constant(std::numbers::pi);
    if (n == "e") return dag_.constant(std::numbers::e);
    if (const auto it = definitions_.find(n); it != definitions_.end()) return it->second;
    if (find_function(n)) fail(t, "'" + n + "' is a function: write " + n + "(...)");
    if (n == defining_) {
      const bool continued =
          source_.substr(defining_offset_, t.offset - defining_offset_).find('\n') != std::string_view::npos;
      fail(t, "'" + n + "' is used in its own definition" +
                  (continued ? " (a line starting with an operator continues the line before)" : ""));
    }
    std::vector<std::string> known = kBuiltinNames;
    known.insert(known.end(), definition_order_.begin(), definition_order_.end());
    fail(t, "unknown name '" + n + "'" + did_you_mean(closest_name(n, known)));
  }

  NodeId call(const Token& t) {
    const std::string n(t.text);
    const Function* f = find_function(n);
    if (!f) {
      const bool known = definitions_.count(n) || n == "x" || n == "y" || n == "z" || n == "pi" || n == "e";
      if (known) fail(t, "'" + n + "' is not a function");
      std::vector<std::string> names;
      for (const Function& g : functions()) names.emplace_back(g.name);
      fail(t, "unknown function '" + n + "'" + did_you_mean(closest_name(n, names)));
    }
    next();  // '('
    std::vector<NodeId> args;
    if (!at(")")) {
      args.push_back(expression());
      while (at(",")) {
        next();
        args.push_back(expression());
      }
    }
    if (!at(")")) fail(peek(), "expected ',' or ')' in the call of " + n + ", found " + describe(peek()));
    next();
    const auto count = static_cast<int>(args.size());
    if (f->variadic ? count < f->arity : count != f->arity) {
      const std::string want = (f->variadic ? "at least " : "") + std::to_string(f->arity) +
                               (f->arity == 1 ? " argument" : " arguments");
      fail(t, n + " takes " + want + ", got " + std::to_string(count));
    }
    if (f->arity == 1) return dag_.unary(f->op, args[0]);
    NodeId r = dag_.binary(f->op, args[0], args[1]);
    for (std::size_t i = 2; i < args.size(); ++i) r = dag_.binary(f->op, r, args[i]);
    return r;
  }

  void check_params() const {
    for (const auto& [name, value] : params_) {
      if (used_params_.count(name)) continue;
      std::string message = "parameter " + name + ": the formula has no definition '" + name + " = ...'";
      if (definition_order_.empty()) {
        message += " (it defines nothing)";
      } else {
        const std::string close = closest_name(name, definition_order_);
        if (!close.empty()) {
          message += did_you_mean(close);
        } else {
          message += " (it defines";
          for (std::size_t i = 0; i < definition_order_.size(); ++i)
            message += (i == 0 ? " " : ", ") + definition_order_[i];
          message += ")";
        }
      }
      throw InputError(message, "params");
    }
  }

  std::string_view source_;
  std::vector<Token> tokens_;
  std::size_t pos_ = 0;
  int depth_ = 0;
  const std::map<std::string, double>& params_;
  Dag& dag_;
  std::map<std::string, NodeId> definitions_;
  std::vector<std::string> definition_order_;
  std::set<std::string> used_params_;
  std::string defining_;  // the definition being parsed, if any
  std::size_t defining_offset_ = 0;
};

}  // namespace

NodeId parse(std::string_view source, const std::map<std::string, double>& params, Dag& dag) {
  return Parser(source, params, dag).program();
}

}  // namespace isopatch::expr
