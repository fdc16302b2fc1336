#include "legacy_io/prime/model_c.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <optional>

#include "legacy_io/common/error.h"
#include "legacy_io/common/input_file.h"
#include "legacy_io/common/text_reader.h"

namespace prime::io {

namespace {

struct Token {
  enum class Kind { Ident, String, Int, Char, Punct, End };
  Kind kind = Kind::End;
  std::string text;  // a string's value (escapes decoded), an integer in decimal
  int line = 0;
};

// C's tokens, as far as a Model.c needs them; comments and preprocessor
// lines are skipped.
class Lexer {
 public:
  Lexer(std::string text, std::string display)
      : text_(std::move(text)), display_(std::move(display)) {
    pos_ = bomLength(text_);
  }

  std::vector<Token> all() {
    std::vector<Token> out;
    for (;;) {
      out.push_back(next());
      if (out.back().kind == Token::Kind::End) return out;
    }
  }

 private:
  [[noreturn]] void fail(int line, const std::string& field, const std::string& expected,
                         const std::string& found) const {
    throw InputError({display_, line, std::nullopt}, field, expected, found);
  }
  bool at(std::size_t i, char c) const { return i < text_.size() && text_[i] == c; }

  void skipSpaceAndComments() {
    bool lineStart = pos_ == bomLength(text_) || (pos_ > 0 && text_[pos_ - 1] == '\n');
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') {
        ++line_;
        ++pos_;
        lineStart = true;
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        ++pos_;
      } else if (c == '/' && at(pos_ + 1, '*')) {
        const int startLine = line_;
        const std::size_t end = text_.find("*/", pos_ + 2);
        if (end == std::string::npos)
          fail(startLine, "comment", "*/ before the end of the file", "no */");
        for (std::size_t i = pos_; i < end; ++i) line_ += text_[i] == '\n';
        pos_ = end + 2;
      } else if (c == '/' && at(pos_ + 1, '/')) {
        while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
      } else if (c == '#' && lineStart) {
        // A preprocessor line (#include, #define), with its continuations.
        while (pos_ < text_.size() && text_[pos_] != '\n') {
          if (text_[pos_] == '\\' && at(pos_ + 1, '\n')) {
            ++line_;
            ++pos_;
          }
          ++pos_;
        }
      } else {
        return;
      }
    }
  }

  // A string or character literal's body, escapes decoded.
  std::string quoted(char quote) {
    const int startLine = line_;
    std::string value;
    ++pos_;
    for (;;) {
      if (pos_ >= text_.size() || text_[pos_] == '\n')
        fail(startLine, quote == '"' ? "string" : "character",
             std::string("a closing ") + quote + " on the same line", "the end of the line");
      const char c = text_[pos_++];
      if (c == quote) return value;
      if (c != '\\') {
        value.push_back(c);
        continue;
      }
      if (pos_ >= text_.size()) continue;
      const char e = text_[pos_++];
      switch (e) {
        case 'n':
          value.push_back('\n');
          break;
        case 't':
          value.push_back('\t');
          break;
        case 'r':
          value.push_back('\r');
          break;
        case '0':
        case '1':
        case '2':
        case '3':
        case '4':
        case '5':
        case '6':
        case '7': {
          int v = e - '0';
          for (int k = 0; k < 2 && pos_ < text_.size() && text_[pos_] >= '0' && text_[pos_] <= '7';
               ++k)
            v = v * 8 + (text_[pos_++] - '0');
          value.push_back(static_cast<char>(v));
          break;
        }
        case 'x': {
          int v = 0;
          while (pos_ < text_.size() && std::isxdigit(static_cast<unsigned char>(text_[pos_]))) {
            const char h =
                static_cast<char>(std::tolower(static_cast<unsigned char>(text_[pos_++])));
            v = (v * 16 + (h <= '9' ? h - '0' : h - 'a' + 10)) & 0xFF;
          }
          value.push_back(static_cast<char>(v));
          break;
        }
        default:
          value.push_back(e);
          break;  // \\ \" \' and the rest as themselves
      }
    }
  }

  Token next() {
    skipSpaceAndComments();
    Token t;
    t.line = line_;
    if (pos_ >= text_.size()) return t;
    const char c = text_[pos_];
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      const std::size_t b = pos_;
      while (pos_ < text_.size() &&
             (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
        ++pos_;
      t.kind = Token::Kind::Ident;
      t.text = text_.substr(b, pos_ - b);
    } else if (std::isdigit(static_cast<unsigned char>(c))) {
      const std::size_t b = pos_;
      while (pos_ < text_.size() && std::isalnum(static_cast<unsigned char>(text_[pos_]))) ++pos_;
      std::string digits = text_.substr(b, pos_ - b);
      while (!digits.empty() && std::strchr("uUlL", digits.back())) digits.pop_back();
      // 0x1F, 017 (octal) and 17, as C reads them; Turbo C's int is 16 bits.
      const int base = digits.size() > 2 && (digits[1] == 'x' || digits[1] == 'X') ? 16
                       : digits.size() > 1 && digits[0] == '0'                     ? 8
                                                                                   : 10;
      const std::string body = base == 16 ? digits.substr(2) : digits;
      std::size_t used = 0;
      long long v = -1;
      try {
        v = std::stoll(body, &used, base);
      } catch (const std::exception&) {
        used = 0;
      }
      if (body.empty() || used != body.size() || v > 32767)
        fail(line_, "integer", "an integer literal of Turbo C's int (at most 32767)",
             doubleQuoted(text_.substr(b, pos_ - b)));
      t.kind = Token::Kind::Int;
      t.text = std::to_string(v);
    } else if (c == '"') {
      t.kind = Token::Kind::String;
      t.text = quoted('"');
    } else if (c == '\'') {
      t.kind = Token::Kind::Char;
      t.text = quoted('\'');
    } else {
      t.kind = Token::Kind::Punct;
      t.text = std::string(1, c);
      ++pos_;
    }
    return t;
  }

  std::string text_, display_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

// What a token is, for "found ..." in messages.
std::string shown(const Token& t) {
  switch (t.kind) {
    case Token::Kind::End:
      return "the end of the file";
    case Token::Kind::String:
      return "the string " + doubleQuoted(t.text);
    case Token::Kind::Char:
      return "the character " + doubleQuoted(t.text);
    case Token::Kind::Int:
      return "the integer " + t.text;
    default:
      return doubleQuoted(t.text);
  }
}

enum class Arg { String, Int };

struct Signature {
  const char* name;
  std::vector<Arg> args;
  bool scene;  // one of the scene's calls (else main()'s housekeeping)
};

const std::vector<Signature>& signatures() {
  static const std::vector<Signature> all = {
      {"AddObj", {Arg::String}, true},
      {"AddToObjList", {Arg::Int}, true},
      {"CopyObj", {Arg::String, Arg::String, Arg::String}, true},
      {"AddMap", {Arg::String}, true},
      {"Message", {Arg::String}, false},
      {"InitFiles", {}, false},
      {"OpenFiles", {}, false},
      {"CloseFiles", {}, false},
      {"FreeAll", {}, false},
      {"Error", {Arg::String}, false}};
  return all;
}

class Parser {
 public:
  Parser(std::vector<Token> tokens, std::string display)
      : t_(std::move(tokens)), display_(std::move(display)) {}

  std::vector<ModelCall> run() {
    findMain();
    expect("{", "main()'s body");
    while (!peekIs("}")) statement(false);
    return std::move(calls_);
  }

 private:
  [[noreturn]] void fail(const Token& at, const std::string& field, const std::string& expected) {
    throw InputError({display_, at.line, std::nullopt}, field, expected, shown(at));
  }
  const Token& peek() const { return t_[std::min(i_, t_.size() - 1)]; }
  bool peekIs(const char* punct) const {
    return peek().kind == Token::Kind::Punct && peek().text == punct;
  }
  const Token& take() {
    const Token& t = peek();
    if (i_ < t_.size() - 1) ++i_;
    return t;
  }
  void expect(const char* punct, const std::string& where) {
    if (!peekIs(punct)) fail(peek(), where, std::string("\"") + punct + "\"");
    take();
  }

  // The definition `main ( ... ) {` at the outermost level (a prototype,
  // `void main(void);`, is passed over).
  void findMain() {
    int depth = 0;
    for (; peek().kind != Token::Kind::End; take()) {
      const Token& t = peek();
      if (t.kind == Token::Kind::Punct && t.text == "{") ++depth;
      if (t.kind == Token::Kind::Punct && t.text == "}") --depth;
      if (depth != 0 || t.kind != Token::Kind::Ident || t.text != "main") continue;
      const std::size_t at = i_;
      take();
      if (!peekIs("(")) {
        i_ = at;
        continue;
      }
      int parens = 0;
      do {
        if (peekIs("(")) ++parens;
        if (peekIs(")")) --parens;
        take();
      } while (parens > 0 && peek().kind != Token::Kind::End);
      if (peekIs("{")) return;
      i_ = at;
    }
    // Blamed on the file's last line: where a main() was still expected.
    throw InputError({display_, peek().line, std::nullopt}, "main()",
                     "the definition of main() whose calls make the scene (void main(void) { "
                     "AddObj(\"d1.txt\"); AddToObjList(1); ... })",
                     "none");
  }

  // One statement of main() (or of its MemoryEmpty check when `inCheck`).
  void statement(bool inCheck) {
    const Token& t = peek();
    if (peekIs(";")) return void(take());
    if (t.kind == Token::Kind::Ident && t.text == "if" && !inCheck) return memoryCheck();
    if (t.kind == Token::Kind::Ident && t.text == "return" && !inCheck) {
      take();
      if (peek().kind == Token::Kind::Int) take();
      expect(";", "return");
      return;
    }
    if (t.kind != Token::Kind::Ident)
      fail(t, "statement of main()",
           "a call of AddObj, AddToObjList, CopyObj or AddMap (or main()'s own Message, "
           "InitFiles, OpenFiles, CloseFiles and MemoryEmpty check)");
    const Signature* sig = nullptr;
    for (const Signature& s : signatures())
      if (t.text == s.name && (!inCheck || !s.scene)) sig = &s;
    if (sig == nullptr)
      fail(t, inCheck ? "statement of main()'s MemoryEmpty check" : "statement of main()",
           inCheck ? "FreeAll(), Error(\"...\") or Message(\"...\")"
                   : "a call of AddObj, AddToObjList, CopyObj or AddMap (or main()'s own "
                     "Message, InitFiles, OpenFiles, CloseFiles and MemoryEmpty check)");
    const Token name = take();
    expect("(", name.text + " call");
    ModelCall call;
    call.name = name.text;
    call.line = name.line;
    for (std::size_t k = 0; k < sig->args.size(); ++k) {
      if (k > 0) expect(",", name.text + " arguments");
      const std::string field = name.text + " argument " + std::to_string(k + 1);
      if (sig->args[k] == Arg::String) {
        if (peek().kind != Token::Kind::String)
          fail(peek(), field, "a string literal (\"d1.txt\")");
        call.args.push_back(take().text);
      } else {
        const bool minus = peekIs("-");
        if (minus) take();
        if (peek().kind != Token::Kind::Int) fail(peek(), field, "an integer literal");
        const std::string digits = take().text;
        call.args.push_back(minus && digits != "0" ? "-" + digits : digits);
      }
    }
    if (!peekIs(")"))
      fail(peek(), name.text + " arguments",
           std::to_string(sig->args.size()) + " argument(s) and \")\"");
    take();
    expect(";", name.text + " call");
    if (sig->scene) calls_.push_back(std::move(call));
  }

  // if (!MemoryEmpty()) { FreeAll(); Error("..."); }: the listing's own check.
  void memoryCheck() {
    take();
    expect("(", "if");
    expect("!", "if (!MemoryEmpty())");
    if (peek().kind != Token::Kind::Ident || peek().text != "MemoryEmpty")
      fail(peek(), "if", "main()'s own check, if (!MemoryEmpty()) { FreeAll(); Error(...); }");
    take();
    expect("(", "MemoryEmpty()");
    expect(")", "MemoryEmpty()");
    expect(")", "if (!MemoryEmpty())");
    if (peekIs("{")) {
      take();
      while (!peekIs("}")) {
        if (peek().kind == Token::Kind::End) fail(peek(), "MemoryEmpty check", "\"}\"");
        statement(true);
      }
      take();
    } else {
      statement(true);
    }
  }

  std::vector<Token> t_;
  std::string display_;
  std::size_t i_ = 0;
  std::vector<ModelCall> calls_;
};

}  // namespace

std::vector<ModelCall> parseModelC(const std::string& text, const std::string& display) {
  std::string body = normalizeLineBreaks(text);  // M21
  endAtDosEof(body);                             // M41
  return Parser(Lexer(std::move(body), display).all(), display).run();
}

}  // namespace prime::io
