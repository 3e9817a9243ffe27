// Output files whose every write is checked. A failed write (disk full, no permission) throws
// veridem::OutputError naming the file, so a run never reports success over lost output.
#pragma once

#include <charconv>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace veridem::io
{

/// A file written under a temporary name (`path` + ".tmp") and renamed over `path` by commit(),
/// so a reader (or a run killed while writing) sees the old file or the new one, never a cut one.
/// Destroyed without commit(), it removes the temporary file.
class AtomicFile
{
  public:
    explicit AtomicFile(std::filesystem::path path);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    std::ofstream& stream() { return out_; }
    /// Flushes, closes and checks the stream, then renames; throws OutputError on any failure.
    void commit();

  private:
    std::filesystem::path path_, temporary_;
    std::ofstream out_;
    bool committed_ = false;
};

/// A file appended to during a run (CSV). flush() writes through and checks the stream.
class AppendFile
{
  public:
    AppendFile() = default;
    /// Creates (truncates) `path`; throws OutputError if it cannot.
    void open(const std::filesystem::path& path);
    /// Continues `path` after a restart: if it exists with at least `bytes` bytes, cuts it to
    /// `bytes` (dropping what a run wrote after its checkpoint) and opens it to append; returns
    /// false (nothing opened) if it does not. Throws OutputError if it cannot.
    bool resume(const std::filesystem::path& path, std::uint64_t bytes);
    /// The file's size after the last write [bytes] (flushes and checks first).
    std::uint64_t size();
    std::ofstream& stream() { return out_; }
    /// Flushes and throws OutputError if any write since the last check failed.
    void flush();
    /// Flushes, closes and checks.
    void close();
    bool isOpen() const { return out_.is_open(); }

  private:
    std::filesystem::path path_;
    std::ofstream out_;
};

/// Throws OutputError "cannot write 'path': reason" (reason from errno if set).
[[noreturn]] void failWrite(const std::filesystem::path& path, const char* what);

/// Appends the shortest decimal form of `value` that reads back to the same double
/// (std::to_chars, round-trip precision).
inline void appendNumber(std::string& out, double value)
{
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

} // namespace veridem::io
