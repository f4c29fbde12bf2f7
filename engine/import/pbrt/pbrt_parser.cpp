#include "import/pbrt/pbrt_parser.h"
#include "scene/gzip_file.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <memory>
#include <system_error>

namespace photon::pbrt {

namespace fs = std::filesystem;

namespace {

// What follows a directive's name.
enum class Arguments {
    Nothing,            // AttributeBegin
    Numbers,            // Translate 1 2 3; Transform [ 16 numbers ]
    Strings,            // NamedMaterial "name"
    StringsThenParams,  // Shape "sphere" "float radius" 2
    ParamsOnly,         // Option "bool disablepixeljitter" true
    OneOrTwoStrings,    // MediumInterface "inside" "outside"
    TimeWord,           // ActiveTransform All
};

struct Signature {
    std::string_view name;
    Arguments arguments;
    size_t count = 0;  // how many numbers or strings
};

constexpr Signature signatures[] = {
    {"AttributeBegin", Arguments::Nothing},
    {"AttributeEnd", Arguments::Nothing},
    {"WorldBegin", Arguments::Nothing},
    {"WorldEnd", Arguments::Nothing},
    {"ObjectEnd", Arguments::Nothing},
    {"ReverseOrientation", Arguments::Nothing},
    {"TransformBegin", Arguments::Nothing},
    {"TransformEnd", Arguments::Nothing},
    {"Identity", Arguments::Nothing},
    {"Translate", Arguments::Numbers, 3},
    {"Scale", Arguments::Numbers, 3},
    {"Rotate", Arguments::Numbers, 4},
    {"LookAt", Arguments::Numbers, 9},
    {"Transform", Arguments::Numbers, 16},
    {"ConcatTransform", Arguments::Numbers, 16},
    {"TransformTimes", Arguments::Numbers, 2},
    {"CoordinateSystem", Arguments::Strings, 1},
    {"CoordSysTransform", Arguments::Strings, 1},
    {"NamedMaterial", Arguments::Strings, 1},
    {"ObjectBegin", Arguments::Strings, 1},
    {"ObjectInstance", Arguments::Strings, 1},
    {"Include", Arguments::Strings, 1},
    {"Import", Arguments::Strings, 1},
    {"ColorSpace", Arguments::Strings, 1},
    {"ActiveTransform", Arguments::TimeWord},
    {"Camera", Arguments::StringsThenParams, 1},
    {"Film", Arguments::StringsThenParams, 1},
    {"Sampler", Arguments::StringsThenParams, 1},
    {"Integrator", Arguments::StringsThenParams, 1},
    {"PixelFilter", Arguments::StringsThenParams, 1},
    {"Accelerator", Arguments::StringsThenParams, 1},
    {"Shape", Arguments::StringsThenParams, 1},
    {"Material", Arguments::StringsThenParams, 1},
    {"LightSource", Arguments::StringsThenParams, 1},
    {"AreaLightSource", Arguments::StringsThenParams, 1},
    {"MakeNamedMaterial", Arguments::StringsThenParams, 1},
    {"MakeNamedMedium", Arguments::StringsThenParams, 1},
    {"Attribute", Arguments::StringsThenParams, 1},
    {"Texture", Arguments::StringsThenParams, 3},
    {"Option", Arguments::ParamsOnly},
    {"MediumInterface", Arguments::OneOrTwoStrings},
};

const Signature* signatureOf(std::string_view name) {
    for (const Signature& s : signatures)
        if (s.name == name) return &s;
    return nullptr;
}

// The kind of value each parameter type takes.
enum class Values { Numbers, Integers, Strings, Bools, NumbersOrStrings };

struct ParamType {
    std::string_view name;
    Values values;
};

constexpr ParamType paramTypes[] = {
    {"float", Values::Numbers},     {"integer", Values::Integers},  {"rgb", Values::Numbers},
    {"color", Values::Numbers},     {"point", Values::Numbers},     {"point2", Values::Numbers},
    {"point3", Values::Numbers},    {"vector", Values::Numbers},    {"vector2", Values::Numbers},
    {"vector3", Values::Numbers},   {"normal", Values::Numbers},    {"normal3", Values::Numbers},
    {"blackbody", Values::Numbers}, {"spectrum", Values::NumbersOrStrings},
    {"string", Values::Strings},    {"texture", Values::Strings},   {"bool", Values::Bools},
};

const ParamType* paramTypeOf(std::string_view name) {
    for (const ParamType& t : paramTypes)
        if (t.name == name) return &t;
    return nullptr;
}

const char* expectation(Values values) {
    switch (values) {
    case Values::Numbers: return "numbers";
    case Values::Integers: return "integers";
    case Values::Strings: return "strings";
    case Values::Bools: return "true or false";
    case Values::NumbersOrStrings: return "numbers or strings";
    }
    return "values";
}

std::string plural(size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

// A token as a message names it: its kind, and for words and strings what it says.
std::string shown(const Token& t) {
    constexpr size_t limit = 40;
    std::string text(t.text.substr(0, limit));
    if (t.text.size() > limit) text += "...";
    switch (t.kind) {
    case TokenKind::Word: return "bare word '" + text + "'";
    case TokenKind::String: return "string \"" + text + "\"";
    case TokenKind::Number: return "number " + text;
    default: return describe(t.kind);
    }
}

// Whether `path` (canonical) is `root` (canonical) or lies under it.
bool isInside(const fs::path& path, const fs::path& root) {
    auto p = path.begin();
    for (auto r = root.begin(); r != root.end(); ++r, ++p) {
        if (r->empty()) continue;  // the empty last part of a root written with a trailing '/'
        if (p == path.end() || *p != *r) return false;
    }
    return true;
}

// A file's `size` bytes (as measured, and checked against the limits, beforehand).
bool readWhole(const fs::path& file, std::uintmax_t size, std::string& text) {
    text.assign(size, '\0');
    std::ifstream in(file, std::ios::binary);
    return bool(in.read(text.data(), std::streamsize(size)));
}

// A gzip-compressed file's text (pbrt-v4 reads "geometry.pbrt.gz" as the text it holds), at
// most `budget` bytes of it; other text as it is. Throws std::runtime_error (gzip_file.h).
void decompressIfGzip(std::string& text, std::uintmax_t budget, const std::string& name) {
    if (isGzip(text)) text = gunzip(text, size_t(std::min<std::uintmax_t>(budget, SIZE_MAX)), name);
}

// What every file of one parse shares: where the scene lives, what it may still read, and
// the chain of files now being read (to refuse a file that includes itself).
struct Session {
    fs::path root;  // canonical
    const std::function<void(Directive&&)>& sink;
    const ParseLimits& limits;
    std::vector<fs::path> chain;  // canonical paths, main file first
    size_t files = 0;
    size_t bytes = 0;
};

// Reads the directives of the main file (or in-memory text) and the files it includes. As
// in pbrt-v4, an included file's tokens stand where its Include was, so a directive that
// its last lines begin may go on in the includer (after it, the rest of a parameter list):
// one stream of tokens, from a stack of open files.
class DirectiveReader {
public:
    DirectiveReader(Session& session, std::string_view text, const std::string& name) : session_(session) {
        open(text, name);
    }

    void run() {
        for (;;) {
            Token t = take();
            if (t.kind == TokenKind::End) return;
            Directive d = directive(t);
            if (d.name == "Include" || d.name == "Import")
                include(d);
            else
                session_.sink(std::move(d));
        }
    }

private:
    // An open file: its text (an include's own; the main file's is the caller's) and tokens.
    struct OpenFile {
        std::string text;
        Tokenizer tokens;
        int source;  // its index in names_
        OpenFile(std::string owned, std::string_view view, const std::string& name, int index)
            : text(std::move(owned)), tokens(text.empty() ? view : std::string_view(text), name), source(index) {}
    };

    void open(std::string_view text, const std::string& name, std::string owned = {}) {
        names_.push_back(name);
        files_.push_back(std::make_unique<OpenFile>(std::move(owned), text, name, static_cast<int>(names_.size()) - 1));
    }

    Location where(const Token& t) const { return {names_[static_cast<size_t>(t.source)], t.line}; }

    [[noreturn]] void fail(const Location& at, const std::string& message) const { throw ParseError(at, message); }
    [[noreturn]] void fail(const Token& at, const std::string& message) const { fail(where(at), message); }

    // The next token of the stream: at the end of an included file, the includer's next.
    Token fetch() {
        for (;;) {
            Token t = files_.back()->tokens.next();
            if (t.kind == TokenKind::End && files_.size() > 1) {
                files_.pop_back();
                session_.chain.pop_back();
                continue;
            }
            t.source = files_.back()->source;
            return t;
        }
    }

    const Token& peek() {
        if (!ahead_) {
            next_ = fetch();
            ahead_ = true;
        }
        return next_;
    }

    Token take() {
        peek();
        ahead_ = false;
        return next_;
    }

    Directive directive(const Token& t) {
        if (t.kind == TokenKind::CloseBracket) fail(t, "unbalanced ']'");
        if (t.kind != TokenKind::Word) fail(t, "expected a directive, found " + shown(t));
        const Signature* signature = signatureOf(t.text);
        if (!signature) fail(t, "unknown directive '" + std::string(t.text.substr(0, 40)) + "'");
        Directive d;
        d.name = signature->name;
        d.where = where(t);
        switch (signature->arguments) {
        case Arguments::Nothing: break;
        case Arguments::Numbers: numbers(d, signature->count); break;
        case Arguments::Strings: strings(d, signature->count, signature->count); break;
        case Arguments::StringsThenParams:
            strings(d, signature->count, signature->count);
            params(d);
            break;
        case Arguments::ParamsOnly: params(d); break;
        case Arguments::OneOrTwoStrings: strings(d, 1, 2); break;
        case Arguments::TimeWord: timeWord(d); break;
        }
        return d;
    }

    // Positional numbers, bare or in brackets ("Transform [ ... ]" and "Transform ..." are
    // both in use), exactly `count` of them.
    void numbers(Directive& d, size_t count) {
        const bool bracketed = peek().kind == TokenKind::OpenBracket;
        if (bracketed) take();
        while (peek().kind == TokenKind::Number) d.numbers.push_back(take().number);
        if (bracketed) {
            Token close = take();
            if (close.kind != TokenKind::CloseBracket)
                fail(close, d.name + ": expected ']' after the numbers, found " + shown(close));
        }
        if (d.numbers.size() != count)
            fail(d.where, d.name + ": expected " + plural(count, "number", "numbers") + ", found " +
                                   std::to_string(d.numbers.size()));
    }

    void strings(Directive& d, size_t least, size_t most) {
        while (d.strings.size() < most && peek().kind == TokenKind::String) d.strings.push_back(unescape(take()));
        if (d.strings.size() < least) {
            std::string wanted = least == most ? plural(least, "string", "strings")
                                               : std::to_string(least) + " or " + plural(most, "string", "strings");
            fail(d.where, d.name + ": expected " + wanted + ", found " + std::to_string(d.strings.size()) +
                                   " before " + shown(peek()));
        }
    }

    void timeWord(Directive& d) {
        Token t = take();
        if (t.kind == TokenKind::Word && (t.text == "All" || t.text == "StartTime" || t.text == "EndTime")) {
            d.strings.emplace_back(t.text);
            return;
        }
        fail(t, d.name + ": expected All, StartTime or EndTime, found " + shown(t));
    }

    void params(Directive& d) {
        while (peek().kind == TokenKind::String) d.params.push_back(param());
    }

    Param param() {
        Token declaration = take();
        Param p;
        p.where = where(declaration);
        const std::string written = unescape(declaration);
        // "type name", blanks around and between allowed, nothing more.
        std::vector<std::string_view> words;
        std::string_view rest = written;
        while (words.size() < 3) {
            size_t begin = rest.find_first_not_of(" \t\r\n");
            if (begin == std::string_view::npos) break;
            rest.remove_prefix(begin);
            size_t end = std::min(rest.find_first_of(" \t\r\n"), rest.size());
            words.push_back(rest.substr(0, end));
            rest.remove_prefix(end);
        }
        if (words.size() != 2)
            fail(declaration, "expected a parameter declaration \"type name\", found " + shown(declaration));
        const ParamType* type = paramTypeOf(words[0]);
        if (!type) fail(declaration, "unknown parameter type '" + std::string(words[0]) + "' in \"" + written + "\"");
        p.type = words[0];
        p.name = words[1];
        const std::string label = "parameter \"" + written + "\"";

        const Token& first = peek();
        if (first.kind == TokenKind::OpenBracket) {
            const Token open = take();
            for (;;) {
                Token v = take();
                if (v.kind == TokenKind::CloseBracket) break;
                if (v.kind == TokenKind::End) fail(open, "unbalanced '[': " + label + " has no ']'");
                if (v.kind == TokenKind::OpenBracket) fail(v, "'[' inside the values of " + label);
                // A directive's name among the values: the ']' was forgotten.
                if (v.kind == TokenKind::Word && signatureOf(v.text))
                    fail(open, "unbalanced '[': " + label + " has no ']' before " + std::string(v.text) +
                                   (v.source == open.source ? " on line " + std::to_string(v.line) : " at " + where(v).str()));
                value(p, type->values, label, v);
            }
        } else if (first.kind == TokenKind::Number || first.kind == TokenKind::String ||
                   (first.kind == TokenKind::Word && (first.text == "true" || first.text == "false"))) {
            value(p, type->values, label, take());
        } else {
            fail(declaration, label + " has no value");
        }
        return p;
    }

    void value(Param& p, Values values, const std::string& label, const Token& v) {
        // Built only when needed: this runs once for each of a mesh's millions of numbers.
        auto wrongKind = [&] { return label + " expects " + expectation(values) + ", found " + shown(v); };
        switch (v.kind) {
        case TokenKind::Number:
            if (values == Values::Integers) {
                if (std::trunc(v.number) != v.number || std::abs(v.number) > 2147483647.0) fail(v, wrongKind());
            } else if (values != Values::Numbers && values != Values::NumbersOrStrings) {
                fail(v, wrongKind());
            }
            if (!p.strings.empty()) fail(v, label + " mixes numbers and strings");
            p.numbers.push_back(v.number);
            return;
        case TokenKind::String:
            if (values == Values::Bools) {
                // pbrt-v3 files write bools quoted.
                if (v.text == "true" || v.text == "false") {
                    p.bools.push_back(v.text == "true");
                    return;
                }
                fail(v, wrongKind());
            }
            if (values != Values::Strings && values != Values::NumbersOrStrings) fail(v, wrongKind());
            if (!p.numbers.empty()) fail(v, label + " mixes numbers and strings");
            p.strings.push_back(unescape(v));
            return;
        case TokenKind::Word:
            if (values == Values::Bools && (v.text == "true" || v.text == "false")) {
                p.bools.push_back(v.text == "true");
                return;
            }
            fail(v, wrongKind());
        default: fail(v, wrongKind());
        }
    }

    void include(const Directive& d) {
        const std::string& written = d.strings.front();
        const std::string quoted = d.name + " \"" + written + "\"";
        Session& s = session_;
        if (written.empty()) fail(d.where, d.name + ": empty file name");
        const fs::path relative(written);
        if (relative.is_absolute())
            fail(d.where, quoted + ": absolute paths are refused; name the file relative to the including file");
        if (s.chain.size() > s.limits.maxIncludeDepth)
            fail(d.where, quoted + ": includes nested more than " + std::to_string(s.limits.maxIncludeDepth) +
                                   " deep");
        const fs::path folder = s.chain.back().parent_path();
        std::error_code error;
        const fs::path target = fs::weakly_canonical(folder / relative, error);
        if (error || !isInside(target, s.root))
            fail(d.where, quoted + ": outside the scene's folder");
        if (!fs::is_regular_file(target, error)) fail(d.where, quoted + ": file not found");
        for (const fs::path& open : s.chain)
            if (open == target) fail(d.where, quoted + ": the file includes itself (an include cycle)");
        if (++s.files > s.limits.maxFiles)
            fail(d.where, quoted + ": more than " + std::to_string(s.limits.maxFiles) + " files read");
        const std::uintmax_t size = fs::file_size(target, error);
        if (error || s.bytes > s.limits.maxTotalBytes || size > s.limits.maxTotalBytes - s.bytes)
            fail(d.where, quoted + ": the scene's files exceed " + std::to_string(s.limits.maxTotalBytes) + " bytes");
        std::string text;
        if (!readWhole(target, size, text)) fail(d.where, quoted + ": cannot be read");
        try {
            decompressIfGzip(text, s.limits.maxTotalBytes - s.bytes, written);
        } catch (const GunzipLimitExceeded&) {
            fail(d.where, quoted + ": the scene's files exceed " + std::to_string(s.limits.maxTotalBytes) + " bytes");
        } catch (const std::runtime_error& e) {
            fail(d.where, d.name + " " + e.what());
        }
        s.bytes += text.size();
        s.chain.push_back(target);
        // The Include is the last token taken: the included file's tokens come next.
        open({}, target.lexically_relative(s.root).generic_string(), std::move(text));
    }

    Session& session_;
    std::vector<std::unique_ptr<OpenFile>> files_;  // the file being read last
    std::vector<std::string> names_;                 // every file opened, by Token::source
    Token next_;
    bool ahead_ = false;
};

void parseInto(Session& session, std::string_view text, const std::string& name) {
    DirectiveReader(session, text, name).run();
}

fs::path canonicalRoot(const fs::path& root, const std::string& name) {
    std::error_code error;
    fs::path canonical = fs::canonical(root.empty() ? fs::path(".") : root, error);
    if (error) throw ParseError({name, 0}, "scene folder '" + root.string() + "' not found");
    return canonical;
}

}  // namespace

const Param* Directive::find(std::string_view wanted) const {
    for (const Param& p : params)
        if (p.name == wanted) return &p;
    return nullptr;
}

void parseText(std::string_view text, const std::string& name, const fs::path& root,
               const std::function<void(Directive&&)>& sink, const ParseLimits& limits) {
    Session session{canonicalRoot(root, name), sink, limits, {}, 1, text.size()};
    if (text.size() > limits.maxTotalBytes)
        throw ParseError({name, 0}, "the scene file exceeds " + std::to_string(limits.maxTotalBytes) + " bytes");
    std::error_code error;
    // The text stands where its name puts it, for its includes' paths and cycles.
    session.chain.push_back(fs::weakly_canonical(session.root / name, error));
    if (error) session.chain.back() = session.root / name;
    parseInto(session, text, name);
}

void parseFile(const fs::path& file, const fs::path& root, const std::function<void(Directive&&)>& sink,
               const ParseLimits& limits) {
    std::string name = file.filename().generic_string();
    const fs::path canonicalRootPath = canonicalRoot(root, name);
    std::error_code error;
    const fs::path target = fs::canonical(file, error);
    if (error || !fs::is_regular_file(target, error)) throw ParseError({name, 0}, "scene file '" + file.string() + "' not found");
    if (isInside(target, canonicalRootPath)) name = target.lexically_relative(canonicalRootPath).generic_string();
    const std::uintmax_t size = fs::file_size(target, error);
    if (error || size > limits.maxTotalBytes)
        throw ParseError({name, 0}, "the scene file exceeds " + std::to_string(limits.maxTotalBytes) + " bytes");
    std::string text;
    if (!readWhole(target, size, text)) throw ParseError({name, 0}, "the scene file cannot be read");
    try {
        decompressIfGzip(text, limits.maxTotalBytes, name);
    } catch (const GunzipLimitExceeded&) {
        throw ParseError({name, 0}, "the scene file exceeds " + std::to_string(limits.maxTotalBytes) + " bytes");
    } catch (const std::runtime_error& e) {
        throw ParseError({name, 0}, e.what());
    }
    Session session{canonicalRootPath, sink, limits, {target}, 1, text.size()};
    parseInto(session, text, name);
}

}  // namespace photon::pbrt
