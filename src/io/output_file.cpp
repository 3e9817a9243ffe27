#include "io/output_file.h"

#include "core/error.h"

#include <cerrno>
#include <cstring>

namespace veridem::io
{

void failWrite(const std::filesystem::path& path, const char* what)
{
    std::string message = "cannot " + std::string(what) + " '" + path.string() + "'";
    if (errno != 0)
        message += ": " + std::string(std::strerror(errno));
    throw OutputError(message);
}

AtomicFile::AtomicFile(std::filesystem::path path) : path_(std::move(path))
{
    temporary_ = path_;
    temporary_ += ".tmp";
    errno = 0;
    out_.open(temporary_, std::ios::binary | std::ios::trunc);
    if (!out_)
        failWrite(temporary_, "create");
    errno = 0;
}

AtomicFile::~AtomicFile()
{
    if (!committed_)
    {
        out_.close();
        std::error_code ignored;
        std::filesystem::remove(temporary_, ignored);
    }
}

void AtomicFile::commit()
{
    out_.flush(); // errno: from the first failed write (reset after every successful check)
    if (!out_)
        failWrite(temporary_, "write");
    out_.close();
    if (out_.fail())
        failWrite(temporary_, "close");
    std::error_code error;
    std::filesystem::rename(temporary_, path_, error);
    if (error)
        throw OutputError("cannot rename '" + temporary_.string() + "' to '" + path_.string() +
                          "': " + error.message());
    committed_ = true;
}

void AppendFile::open(const std::filesystem::path& path)
{
    path_ = path;
    errno = 0;
    out_.open(path, std::ios::binary | std::ios::trunc);
    if (!out_)
        failWrite(path, "create");
    errno = 0;
}

bool AppendFile::resume(const std::filesystem::path& path, std::uint64_t bytes)
{
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error) || std::filesystem::file_size(path, error) < bytes ||
        error)
        return false;
    std::filesystem::resize_file(path, bytes, error);
    if (error)
        throw OutputError("cannot cut '" + path.string() +
                          "' to its size at the checkpoint: " + error.message());
    path_ = path;
    errno = 0;
    out_.open(path, std::ios::binary | std::ios::in | std::ios::out);
    if (!out_)
        failWrite(path, "open");
    out_.seekp(static_cast<std::streamoff>(bytes));
    if (!out_)
        failWrite(path, "seek in");
    errno = 0;
    return true;
}

std::uint64_t AppendFile::size()
{
    flush();
    const auto position = out_.tellp();
    if (position < 0)
        failWrite(path_, "tell the size of");
    return static_cast<std::uint64_t>(position);
}

void AppendFile::flush()
{
    out_.flush();
    if (!out_)
        failWrite(path_, "write"); // errno: from the first failed write
    errno = 0;
}

void AppendFile::close()
{
    if (!out_.is_open())
        return;
    flush();
    out_.close();
    if (out_.fail())
        failWrite(path_, "close");
}

} // namespace veridem::io
