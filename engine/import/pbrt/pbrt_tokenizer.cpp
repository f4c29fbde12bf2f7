#include "import/pbrt/pbrt_tokenizer.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <system_error>

namespace photon::pbrt {

namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isLetter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
// What ends a number: the next token may follow without a blank ("[1 2 3]").
bool endsNumber(char c) { return isBlank(c) || c == '[' || c == ']' || c == '"' || c == '#'; }

// A character as a message shows it: printable ASCII as itself, anything else as \xNN.
std::string shown(char c) {
    if (c > ' ' && c < 127) return std::string(1, c);
    static const char* hex = "0123456789abcdef";
    unsigned char u = static_cast<unsigned char>(c);
    return std::string("\\x") + hex[u >> 4] + hex[u & 15];
}

// The escapes pbrt-v4 knows, and what they stand for (0: not an escape).
char escaped(char c) {
    switch (c) {
    case '"': return '"';
    case '\\': return '\\';
    case '\'': return '\'';
    case 'n': return '\n';
    case 't': return '\t';
    case 'r': return '\r';
    case 'b': return '\b';
    case 'f': return '\f';
    default: return 0;
    }
}

// Messages quote what was written, cut short: a malformed "number" may be megabytes long.
std::string excerpt(std::string_view s) {
    constexpr size_t limit = 40;
    return s.size() <= limit ? std::string(s) : std::string(s.substr(0, limit)) + "...";
}

}  // namespace

std::string Location::str() const { return file + ":" + std::to_string(line); }

ParseError::ParseError(Location where, const std::string& message)
    : std::runtime_error(where.str() + ": " + message), where_(std::move(where)), message_(message) {}

const char* describe(TokenKind kind) {
    switch (kind) {
    case TokenKind::Word: return "a bare word";
    case TokenKind::String: return "a string";
    case TokenKind::Number: return "a number";
    case TokenKind::OpenBracket: return "'['";
    case TokenKind::CloseBracket: return "']'";
    case TokenKind::End: return "the end of the file";
    }
    return "a token";
}

std::string unescape(const Token& string) {
    if (!string.escaped) return std::string(string.text);
    std::string out;
    out.reserve(string.text.size());
    for (size_t i = 0; i < string.text.size(); ++i) {
        char c = string.text[i];
        // The tokenizer accepted only known escapes, each followed by its character.
        if (c == '\\' && i + 1 < string.text.size()) c = escaped(string.text[++i]);
        out += c;
    }
    return out;
}

Tokenizer::Tokenizer(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {}

void Tokenizer::skipBlanksAndComments() {
    while (pos_ < text_.size()) {
        char c = text_[pos_];
        if (c == '\n') {
            ++line_;
            ++pos_;
        } else if (isBlank(c)) {
            ++pos_;
        } else if (c == '#') {
            size_t eol = text_.find('\n', pos_);
            pos_ = eol == std::string_view::npos ? text_.size() : eol;
        } else {
            return;
        }
    }
}

Token Tokenizer::next() {
    skipBlanksAndComments();
    if (pos_ >= text_.size()) return {TokenKind::End, {}, 0, false, line_};
    char c = text_[pos_];
    if (c == '[' || c == ']') {
        Token t{c == '[' ? TokenKind::OpenBracket : TokenKind::CloseBracket, text_.substr(pos_, 1), 0, false, line_};
        ++pos_;
        return t;
    }
    if (c == '"') return readString();
    if (isDigit(c) || c == '-' || c == '+' || c == '.') return readNumber();
    if (isLetter(c)) return readWord();
    throw ParseError(at(line_), "unexpected character '" + shown(c) + "'");
}

Token Tokenizer::readString() {
    const int startLine = line_;
    const size_t begin = ++pos_;  // past the opening quote
    bool escapes = false;
    while (pos_ < text_.size()) {
        char c = text_[pos_];
        if (c == '"') {
            Token t{TokenKind::String, text_.substr(begin, pos_ - begin), 0, escapes, startLine};
            ++pos_;
            return t;
        }
        // pbrt-v4 ends a string at the line's end, so a missing quote is reported where
        // the string began rather than swallowing the rest of the file.
        if (c == '\n') break;
        if (c == '\\') {
            if (pos_ + 1 >= text_.size() || text_[pos_ + 1] == '\n') break;
            if (!escaped(text_[pos_ + 1]))
                throw ParseError(at(line_), "unknown escape '\\" + shown(text_[pos_ + 1]) + "' in a string");
            escapes = true;
            ++pos_;
        }
        ++pos_;
    }
    throw ParseError(at(startLine), "unterminated string");
}

Token Tokenizer::readNumber() {
    const size_t begin = pos_;
    while (pos_ < text_.size() && !endsNumber(text_[pos_])) ++pos_;
    const std::string_view written = text_.substr(begin, pos_ - begin);
    // from_chars takes neither a leading '+' nor, sensibly, "-inf" or "-nan": a digit or a
    // point must follow the sign.
    std::string_view digits = written;
    if (!digits.empty() && (digits[0] == '+' || digits[0] == '-')) digits.remove_prefix(1);
    if (digits.empty() || !(isDigit(digits[0]) || digits[0] == '.'))
        throw ParseError(at(line_), "malformed number '" + excerpt(written) + "'");
    const char* first = written[0] == '+' ? written.data() + 1 : written.data();
    const char* last = written.data() + written.size();
    double value = 0;
    auto [end, error] = std::from_chars(first, last, value);
    if (end != last || error == std::errc::invalid_argument)
        throw ParseError(at(line_), "malformed number '" + excerpt(written) + "'");
    if (error == std::errc::result_out_of_range) {
        // Too small rounds to zero (or a subnormal) as strtod would; too large is an error.
        std::string copy(first, last);
        value = std::strtod(copy.c_str(), nullptr);
        if (std::isinf(value)) throw ParseError(at(line_), "number '" + excerpt(written) + "' is out of range");
    }
    return {TokenKind::Number, written, value, false, line_};
}

Token Tokenizer::readWord() {
    const size_t begin = pos_;
    while (pos_ < text_.size() && (isLetter(text_[pos_]) || isDigit(text_[pos_]))) ++pos_;
    return {TokenKind::Word, text_.substr(begin, pos_ - begin), 0, false, line_};
}

}  // namespace photon::pbrt
