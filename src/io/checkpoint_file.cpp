#include "io/checkpoint_file.h"

#include "core/error.h"

#include <array>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <unistd.h>

namespace veridem::io
{

namespace
{

constexpr char kMagic[8] = {'V', 'D', 'M', 'C', 'K', 'P', 'T', '\0'};
constexpr char kEndMagic[8] = {'V', 'D', 'M', 'C', 'K', 'E', 'N', 'D'};
constexpr std::uint32_t kByteOrderMark = 0x01020304u;
constexpr std::uint64_t kChecksumStart = 0xcbf29ce484222325ull;
constexpr std::size_t kHeaderBytes = 32, kTrailerBytes = 24, kRecordHeaderBytes = 16;

struct Header
{
    char magic[8];
    std::uint32_t byteOrder, version, engine, zero;
    std::uint64_t sceneHash;
};
static_assert(sizeof(Header) == kHeaderBytes);

struct Trailer
{
    std::uint64_t payloadBytes, checksum;
    char magic[8];
};
static_assert(sizeof(Trailer) == kTrailerBytes);

struct RecordHeader
{
    char tag[4];
    std::uint32_t size;
    std::uint64_t count;
};
static_assert(sizeof(RecordHeader) == kRecordHeaderBytes);

const char* engineName(std::uint32_t engine)
{
    return engine == 1 ? "3D DEM" : engine == 2 ? "2D FEM/DEM" : "unknown";
}

[[noreturn]] void failOutput(const std::filesystem::path& path, const char* what)
{
    std::string message = "cannot " + std::string(what) + " '" + path.string() + "'";
    if (errno != 0)
        message += ": " + std::string(std::strerror(errno));
    throw OutputError(message);
}

} // namespace

std::uint64_t sceneFileHash(const std::filesystem::path& file)
{
    std::ifstream in(file, std::ios::binary);
    if (!in)
        throw InputError(file.string() + ": cannot be read");
    std::uint64_t hash = kChecksumStart;
    std::array<char, 1 << 16> buffer;
    while (in)
    {
        in.read(buffer.data(), buffer.size());
        for (std::streamsize k = 0; k < in.gcount(); ++k)
        {
            hash ^= static_cast<unsigned char>(buffer[static_cast<std::size_t>(k)]);
            hash *= 0x100000001b3ull;
        }
    }
    if (in.bad())
        throw InputError(file.string() + ": cannot be read");
    return hash;
}

std::uint64_t CheckpointWriter::mix(std::uint64_t hash, const void* data, std::size_t n)
{
    // Each step is a bijection of the running value for a given word, so a changed word always
    // changes the result; the rotation carries the high bits of the product down.
    const auto* bytes = static_cast<const unsigned char*>(data);
    std::size_t k = 0;
    for (; k + 8 <= n; k += 8)
    {
        std::uint64_t word;
        std::memcpy(&word, bytes + k, 8);
        hash = (hash ^ word) * 0x9e3779b97f4a7c15ull;
        hash = (hash << 31) | (hash >> 33);
    }
    for (; k < n; ++k)
        hash = (hash ^ bytes[k]) * 0x100000001b3ull;
    return hash;
}

CheckpointWriter::CheckpointWriter(std::filesystem::path path, CheckpointEngine engine,
                                   std::uint64_t sceneHash)
    : path_(std::move(path)), checksum_(kChecksumStart)
{
    temporary_ = path_;
    temporary_ += ".tmp";
    errno = 0;
    file_ = std::fopen(temporary_.c_str(), "wb");
    if (!file_)
        failOutput(temporary_, "create");
    Header header{};
    std::memcpy(header.magic, kMagic, 8);
    header.byteOrder = kByteOrderMark;
    header.version = kCheckpointVersion;
    header.engine = static_cast<std::uint32_t>(engine);
    header.sceneHash = sceneHash;
    write(&header, sizeof header);
}

CheckpointWriter::~CheckpointWriter()
{
    if (file_)
    {
        std::fclose(file_);
        std::error_code ignored;
        std::filesystem::remove(temporary_, ignored);
    }
}

void CheckpointWriter::write(const void* data, std::size_t n)
{
    errno = 0;
    if (n > 0 && std::fwrite(data, 1, n, file_) != n)
        failOutput(temporary_, "write");
}

void CheckpointWriter::bytes(const char (&tag)[5], const void* data, std::uint32_t size, std::uint64_t count)
{
    RecordHeader record{};
    std::memcpy(record.tag, tag, 4);
    record.size = size;
    record.count = count;
    const std::size_t n = static_cast<std::size_t>(size * count);
    checksum_ = mix(checksum_, &record, sizeof record);
    checksum_ = mix(checksum_, data, n);
    write(&record, sizeof record);
    write(data, n);
    payloadBytes_ += sizeof record + n;
}

void CheckpointWriter::commit()
{
    Trailer trailer{};
    trailer.payloadBytes = payloadBytes_;
    trailer.checksum = checksum_;
    std::memcpy(trailer.magic, kEndMagic, 8);
    write(&trailer, sizeof trailer);
    errno = 0;
    if (std::fflush(file_) != 0)
        failOutput(temporary_, "write");
    if (::fsync(fileno(file_)) != 0)
        failOutput(temporary_, "sync");
    std::FILE* file = file_;
    file_ = nullptr;
    if (std::fclose(file) != 0)
    {
        std::error_code ignored;
        std::filesystem::remove(temporary_, ignored);
        failOutput(temporary_, "close");
    }
    std::error_code error;
    std::filesystem::rename(temporary_, path_, error);
    if (error)
        throw OutputError("cannot rename '" + temporary_.string() + "' to '" + path_.string() +
                          "': " + error.message());
    // The rename itself reaches the disk with the directory.
    std::filesystem::path directory = path_.parent_path();
    if (directory.empty())
        directory = ".";
    errno = 0;
    const int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY);
    if (fd < 0)
        failOutput(directory, "open the directory");
    const bool synced = ::fsync(fd) == 0 || errno == EINVAL; // (a file system without directory sync)
    ::close(fd);
    if (!synced)
        failOutput(directory, "sync the directory");
}

CheckpointReader::CheckpointReader(std::filesystem::path path, CheckpointEngine engine,
                                   std::uint64_t sceneHash)
    : path_(std::move(path)), checksum_(kChecksumStart)
{
    std::error_code error;
    if (!std::filesystem::exists(path_, error))
        fail("does not exist");
    if (!std::filesystem::is_regular_file(path_, error))
        fail("is not a regular file");
    const std::uintmax_t size = std::filesystem::file_size(path_, error);
    if (error)
        fail("cannot read its size: " + error.message());
    file_ = std::fopen(path_.c_str(), "rb");
    if (!file_)
        fail(std::string("cannot be opened: ") + std::strerror(errno));
    try
    {
        if (size < kHeaderBytes + kTrailerBytes)
            fail("is truncated (" + std::to_string(size) + " bytes, less than a header and a trailer)");
        Header header{};
        if (std::fread(&header, sizeof header, 1, file_) != 1)
            fail("cannot read the header");
        if (std::memcmp(header.magic, kMagic, 8) != 0)
            fail("is not a veridem checkpoint (no VDMCKPT magic)");
        if (header.byteOrder != kByteOrderMark)
            fail("was written on a machine of the other byte order");
        if (header.version != kCheckpointVersion)
            fail("has format version " + std::to_string(header.version) + ", this veridem reads version " +
                 std::to_string(kCheckpointVersion));
        if (header.engine != static_cast<std::uint32_t>(engine))
            fail(std::string("is a checkpoint of a ") + engineName(header.engine) + " scene, not of a " +
                 engineName(static_cast<std::uint32_t>(engine)) + " scene");
        if (header.zero != 0)
            fail("is corrupt: its header's reserved word is not 0");
        if (header.sceneHash != sceneHash)
            fail("belongs to another scene (the scene file's hash differs; restart with the scene file it "
                 "was written from, unchanged)");
        Trailer trailer{};
        if (std::fseek(file_, static_cast<long>(size - kTrailerBytes), SEEK_SET) != 0 ||
            std::fread(&trailer, sizeof trailer, 1, file_) != 1)
            fail("cannot read the trailer");
        if (std::memcmp(trailer.magic, kEndMagic, 8) != 0 ||
            trailer.payloadBytes != size - kHeaderBytes - kTrailerBytes)
            fail("is truncated or corrupt (" + std::to_string(size) + " bytes; the trailer does not match)");
        payloadBytes_ = trailer.payloadBytes;
        expectedChecksum_ = trailer.checksum;
        if (std::fseek(file_, static_cast<long>(kHeaderBytes), SEEK_SET) != 0)
            fail("cannot be read");
    }
    catch (...)
    {
        // (A constructor that throws runs no destructor: close the file here, or every refused
        // checkpoint leaks a descriptor.)
        std::fclose(file_);
        file_ = nullptr;
        throw;
    }
}

CheckpointReader::~CheckpointReader()
{
    if (file_)
        std::fclose(file_);
}

void CheckpointReader::fail(const std::string& what) const
{
    throw InputError("checkpoint '" + path_.string() + "' " + what);
}

std::uint64_t CheckpointReader::header(const char (&tag)[5], std::uint32_t size, bool exact,
                                       std::uint64_t count)
{
    RecordHeader record{};
    if (payloadBytes_ - consumed_ < sizeof record)
        fail("is corrupt: record '" + std::string(tag) + "' is missing");
    read(&record, sizeof record);
    if (std::memcmp(record.tag, tag, 4) != 0)
        fail("is corrupt: expected record '" + std::string(tag) + "', found '" + std::string(record.tag, 4) +
             "'");
    if (record.size != size)
        fail("is corrupt: record '" + std::string(tag) + "' has elements of " + std::to_string(record.size) +
             " bytes, expected " + std::to_string(size));
    if (exact && record.count != count)
        fail("is corrupt: record '" + std::string(tag) + "' has " + std::to_string(record.count) +
             " elements, expected " + std::to_string(count));
    if (record.count > (payloadBytes_ - consumed_) / size)
        fail("is corrupt: record '" + std::string(tag) + "' claims " + std::to_string(record.count) +
             " elements, more than the file holds");
    return record.count;
}

void CheckpointReader::read(void* data, std::size_t n)
{
    if (n == 0)
        return;
    if (std::fread(data, 1, n, file_) != n)
        fail("cannot be read (truncated while reading?)");
    consumed_ += n;
    checksum_ = CheckpointWriter::mix(checksum_, data, n);
}

void CheckpointReader::finish()
{
    if (consumed_ != payloadBytes_)
        fail("is corrupt: " + std::to_string(payloadBytes_ - consumed_) +
             " bytes left after the last record");
    if (checksum_ != expectedChecksum_)
        fail("is corrupt: its checksum does not match its contents");
}

} // namespace veridem::io
