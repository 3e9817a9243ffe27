#include "io/toml_guard.h"

#include "core/error.h"

#include <algorithm>

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
                lineStart_ = false;
                skipString();
            }
            else if (c == ' ' || c == '\t' || c == '\r')
                ++i_;
            else if (c == '[' && lineStart_ && depth_ == 0)
                header();
            else
            {
                checkAscii(c);
                lineStart_ = false;
                if (c == '[' || c == '{')
                    ++depth_;
                else if ((c == ']' || c == '}') && depth_ > 0)
                    --depth_;
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
    }

    bool at(std::string_view s) const { return text_.substr(i_, s.size()) == s; }

    void skipComment()
    {
        while (i_ < text_.size() && text_[i_] != '\n')
            ++i_;
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
                else if (quote == '"' && text_[i_] == '\\' && i_ + 1 < text_.size() && text_[i_ + 1] != '\n')
                    ++i_;
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
            if (quote == '"' && text_[i_] == '\\' && i_ + 1 < text_.size() && text_[i_ + 1] != '\n')
                ++i_;
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
    }

    std::string_view text_;
    const std::string& file_;
    std::size_t i_ = 0;
    std::size_t line_ = 1;
    int depth_ = 0;         // [ ] and { } nesting inside a value
    bool lineStart_ = true; // nothing but blanks so far on this line
};

} // namespace

void checkTomlText(std::string_view text, const std::string& file)
{
    Scanner(text, file).run();
}

} // namespace veridem::io
