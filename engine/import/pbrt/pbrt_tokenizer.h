// The lexical layer of pbrt scene files (https://pbrt.org/fileformat-v4): the text cut into
// bare words, quoted strings, numbers and brackets, each with its line. Tokens view the text
// (nothing is copied), and numbers are converted in place, so that the megabytes of numbers
// in an inline triangle mesh cost no allocation.
#pragma once
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace photon::pbrt {

// Where a token came from: the file as named relative to the main scene file's folder
// (generic form, e.g. "scene.pbrt", "geometry/walls.pbrt"), and its 1-based line.
struct Location {
    std::string file;
    int line = 0;
    std::string str() const;  // "file:line"
};

// Any error in a scene file's syntax; what() reads "file:line: message".
class ParseError : public std::runtime_error {
public:
    ParseError(Location where, const std::string& message);
    const Location& where() const { return where_; }
    // The message alone, without the location.
    const std::string& message() const { return message_; }

private:
    Location where_;
    std::string message_;
};

enum class TokenKind { Word, String, Number, OpenBracket, CloseBracket, End };

struct Token {
    TokenKind kind = TokenKind::End;
    // Word: the word. String: the characters between the quotes, escapes still written
    // (see unescape). Number: the number as written. Brackets: "[" or "]". End: empty.
    std::string_view text;
    double number = 0;      // Number tokens only
    bool escaped = false;   // a String holding at least one backslash
    int line = 0;
    int source = 0;  // the file it came from, as the parser numbers the files it reads
};

// "a word", "a string", ... for messages.
const char* describe(TokenKind kind);

// A string token's value, its escapes (\" \\ \n \t \r \b \f) replaced.
std::string unescape(const Token& string);

class Tokenizer {
public:
    // `text` must outlive the tokenizer and its tokens; `file` names it in errors.
    Tokenizer(std::string_view text, std::string file);

    // The next token, or an End token at the end of the text. Throws ParseError for an
    // unterminated string, a malformed or out-of-range number, or a stray character.
    Token next();

    const std::string& file() const { return file_; }
    Location at(int line) const { return {file_, line}; }

private:
    void skipBlanksAndComments();
    Token readString();
    Token readNumber();
    Token readWord();

    std::string_view text_;
    std::string file_;
    size_t pos_ = 0;
    int line_ = 1;
};

}  // namespace photon::pbrt
