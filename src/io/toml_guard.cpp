#include "io/toml_guard.h"

#include "core/error.h"

#include <algorithm>
#include <cstdint>

namespace veridem::io
{

namespace
{

bool isBareKeyChar(char c)
{
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
}

class Scanner
{
  public:
    Scanner(std::string_view text, const std::string& file) : text_(text), file_(file) {}

    void run()
    {
        while (i_ < text_.size())
        {
            const char c = text_[i_];
            if (c == '\n')
            {
                newLine();
                ++i_;
            }
            else if (c == '#')
                skipComment();
            else if (c == '"' || c == '\'')
            {
                // A string starts a key or a value: at the line start or after = [ , { or a
                // dot. Elsewhere (inside a bare value) it is malformed, and toml++ 3.3.0 can reach
                // undefined behaviour on the text that follows (found by fuzzing).
                const bool starts = lineStart_ ||
                                    std::string_view("=[,{").find(last_) != std::string_view::npos ||
                                    (last_ == '.' && inKey_);
                if (!starts)
                    fail(std::string("misplaced ") + c + ": a string must start a key or a value");
                lineStart_ = false;
                skipString();
                last_ = c;
            }
            else if (c == ' ' || c == '\t' || c == '\r')
                ++i_;
            else if (c == '[' && lineStart_ && depth_ == 0)
                header();
            else
            {
                checkAscii(c);
                // An array or inline table starts a value: after = [ or , (a header is handled
                // above). After anything else toml++ 3.3.0 can reach undefined behaviour on the
                // text that follows (found by fuzzing: "duration = 1[[...[\"...").
                if ((c == '[' || c == '{') && std::string_view("=[,").find(last_) == std::string_view::npos)
                    fail(std::string("misplaced ") + c + ": an array or inline table must start a value");
                if (c == '=' && !inKey_) // a second '=' in a value ("u = 0b0w=\"...": found by fuzzing)
                    fail("misplaced '=': one key = value per line");
                lineStart_ = false;
                last_ = c;
                if (c == '[' || c == '{')
                {
                    ++depth_;
                    open_.push_back(c);
                    inKey_ = c == '{';
                }
                else if ((c == ']' || c == '}') && depth_ > 0)
                {
                    --depth_;
                    open_.pop_back();
                    inKey_ = false;
                }
                else if (c == '=')
                    inKey_ = false;
                else if (c == ',')
                    inKey_ = !open_.empty() && open_.back() == '{';
                ++i_;
            }
        }
    }

  private:
    [[noreturn]] void fail(const std::string& what) const
    {
        throw InputError(file_ + ":" + std::to_string(line_) + ": " + what);
    }

    void checkAscii(char c) const
    {
        if (static_cast<unsigned char>(c) >= 0x80)
            fail("non-ASCII character outside a string or comment: a bare key may hold only A-Z a-z 0-9 _ - "
                 "(quote the key, e.g. \"densit\xC3\xA9\" = ..., or use an ASCII name)");
    }

    void newLine()
    {
        ++line_;
        lineStart_ = true;
        if (depth_ == 0)
            inKey_ = true;
    }

    bool at(std::string_view s) const { return text_.substr(i_, s.size()) == s; }

    void skipComment()
    {
        while (i_ < text_.size() && text_[i_] != '\n')
            ++i_;
    }

    /// At a backslash in a basic string: steps over the escaped character, or over the blanks and
    /// line ends after a line-ending backslash, refusing a non-ASCII character after the backslash
    /// (and its blanks) or right after the trimmed line ends: toml++ 3.3.0 tests that character for
    /// Unicode whitespace and reaches undefined behaviour for many code points, e.g. U+00E9, U+FE7F
    /// or U+FEDF (found by fuzzing). Leaves i_ on the last character stepped over.
    void escape()
    {
        std::size_t j = i_ + 1;
        while (j < text_.size() && (text_[j] == ' ' || text_[j] == '\t' || text_[j] == '\r'))
            ++j;
        if (j < text_.size() && static_cast<unsigned char>(text_[j]) >= 0x80)
            fail("non-ASCII character after a backslash in a string (not an escape sequence)");
        if (j >= text_.size() || text_[j] != '\n')
        {
            if (i_ + 1 < text_.size() && text_[i_ + 1] != '\n')
                ++i_; // an escape sequence such as \" or \\ (checked by the TOML library)
            return;
        }
        while (j < text_.size() &&
               (text_[j] == ' ' || text_[j] == '\t' || text_[j] == '\r' || text_[j] == '\n'))
        {
            if (text_[j] == '\n')
                ++line_;
            ++j;
        }
        if (j < text_.size() && static_cast<unsigned char>(text_[j]) >= 0x80)
            fail("non-ASCII character right after a line-ending backslash in a string (put an ASCII "
                 "character first)");
        i_ = j - 1;
    }

    /// Skips a basic, literal or multi-line string starting at i_. An unterminated single-line
    /// string ends at the line end (the TOML library reports it).
    void skipString()
    {
        const char quote = text_[i_];
        const std::string triple(3, quote);
        if (at(triple))
        {
            i_ += 3;
            while (i_ < text_.size() && !at(triple))
            {
                if (text_[i_] == '\n')
                    ++line_;
                else if (quote == '"' && text_[i_] == '\\')
                    escape();
                ++i_;
            }
            i_ = std::min(text_.size(), i_ + 3);
            while (i_ < text_.size() && text_[i_] == quote) // up to two quotes may close the string
                ++i_;
            return;
        }
        ++i_;
        while (i_ < text_.size() && text_[i_] != quote && text_[i_] != '\n')
        {
            if (quote == '"' && text_[i_] == '\\')
                escape();
            ++i_;
        }
        if (i_ < text_.size() && text_[i_] == quote)
            ++i_;
    }

    void skipBlanks()
    {
        while (i_ < text_.size() && (text_[i_] == ' ' || text_[i_] == '\t'))
            ++i_;
    }

    /// [key(.key)*] or [[key(.key)*]], then blanks, an optional comment and the line end.
    void header()
    {
        const char* expected =
            "a table header must be [name] or [[name]] with dotted keys of A-Z a-z 0-9 _ - "
            "or quoted keys";
        ++i_;
        const bool array = i_ < text_.size() && text_[i_] == '[';
        if (array)
            ++i_;
        for (;;)
        {
            skipBlanks();
            if (i_ >= text_.size())
                fail(expected);
            const char c = text_[i_];
            if (c == '"' || c == '\'')
            {
                const std::size_t line = line_;
                skipString();
                if (line_ != line || text_[i_ - 1] != c)
                    fail(expected);
            }
            else if (isBareKeyChar(c))
                while (i_ < text_.size() && isBareKeyChar(text_[i_]))
                    ++i_;
            else
            {
                checkAscii(c);
                fail(expected);
            }
            skipBlanks();
            if (i_ < text_.size() && text_[i_] == '.')
            {
                ++i_;
                continue;
            }
            break;
        }
        if (!at(array ? "]]" : "]"))
        {
            if (i_ < text_.size())
                checkAscii(text_[i_]);
            fail(expected);
        }
        i_ += array ? 2 : 1;
        skipBlanks();
        if (i_ < text_.size() && text_[i_] == '#')
            skipComment();
        if (i_ < text_.size() && text_[i_] == '\r')
            ++i_;
        if (i_ < text_.size() && text_[i_] != '\n')
            fail(std::string(expected) + ", alone on its line");
        lineStart_ = false;
        last_ = ']';
    }

    std::string_view text_;
    const std::string& file_;
    std::size_t i_ = 0;
    std::size_t line_ = 1;
    int depth_ = 0;         // [ ] and { } nesting inside a value
    char last_ = '\n';      // the last character outside strings, comments and blanks
    bool lineStart_ = true; // nothing but blanks so far on this line
    bool inKey_ = true;     // a key is being read (before '=', or in an inline table after { or ,)
    std::string open_;      // the open [ and { of values, innermost last
};

/// TOML text is UTF-8 without control characters other than tab, line feed and carriage return.
void checkEncoding(std::string_view text, const std::string& file)
{
    std::size_t line = 1;
    auto fail = [&](const std::string& what)
    { throw InputError(file + ":" + std::to_string(line) + ": " + what + " (a scene is UTF-8 text)"); };
    for (std::size_t i = 0; i < text.size();)
    {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c < 0x80)
        {
            if (c == '\n')
                ++line;
            else if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7F)
                fail("control character " + std::to_string(c));
            ++i;
            continue;
        }
        // Length and smallest code point of the sequence; continuation bytes are 10xxxxxx.
        const std::size_t length = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC0 ? 2 : 0;
        if (length == 0 || c > 0xF4 || i + length > text.size())
            fail("invalid UTF-8");
        std::uint32_t code = c & (0x7F >> length);
        for (std::size_t k = 1; k < length; ++k)
        {
            const auto next = static_cast<unsigned char>(text[i + k]);
            if ((next & 0xC0) != 0x80)
                fail("invalid UTF-8");
            code = (code << 6) | (next & 0x3F);
        }
        const std::uint32_t smallest = length == 2 ? 0x80 : length == 3 ? 0x800 : 0x10000;
        if (code < smallest || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF))
            fail("invalid UTF-8");
        i += length;
    }
}

} // namespace

void checkTomlText(std::string_view text, const std::string& file)
{
    checkEncoding(text, file);
    Scanner(text, file).run();
}

} // namespace veridem::io
