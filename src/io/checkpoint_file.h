// The binary container of a checkpoint (docs/scene-format.md, "Checkpoint and restart"): a header,
// a payload of tagged records written as they are in memory, and a trailer.
//
//   header   magic "VDMCKPT\0" (8 B), byte-order mark 0x01020304 (u32, native order), format
//            version (u32), engine (u32: 1 = 3D DEM, 2 = 2D FEM/DEM), 0 (u32), scene hash (u64:
//            FNV-1a 64 of the scene file's bytes)                                          32 B
//   payload  records: tag (4 characters), element size (u32, bytes), element count (u64), then
//            count * size bytes, the array's elements as they are in memory
//   trailer  payload bytes (u64), payload checksum (u64, CheckpointWriter::mix over every record),
//            magic "VDMCKEND"                                                              24 B
//
// The writer writes DIR/NAME.tmp with large fwrite blocks, checks every write, fsyncs, closes and
// renames it over NAME (then fsyncs the directory), so a checkpoint on disk is always a complete
// one. The reader checks the header, the file size against the trailer, each record's tag, element
// size and count against what is left, and the checksum, so a truncated or corrupt file is an
// InputError (one line), never a crash or a wrong state.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <type_traits>
#include <vector>

namespace veridem::io
{

inline constexpr std::uint32_t kCheckpointVersion = 6; // 2: the 3D energy ledger records (enLg, enSt); 3: its
                                                       // adhesion dissipation; 4: particle ids and frozen
                                                       // flags, inserter and outlet state (pId, pFix, fl*);
                                                       // 5: the periodic pairs and their history (pb*);
                                                       // 6: the flat mesh slots' triangles (wcMF)

enum class CheckpointEngine : std::uint32_t
{
    Dem3d = 1,
    Fdem2d = 2,
};

/// What a run driver needs to continue its output files after a restart.
struct CheckpointOutputs
{
    std::vector<double> frameTimes;       // output time of each frame written so far [s]
    std::vector<std::uint64_t> fileBytes; // size of each CSV file at the checkpoint [bytes], in the
                                          // driver's order
    double timeOrigin = 0;                // time subtracted from the output times [s] (2D settling)
};

/// FNV-1a 64 of the bytes of `file` (the scene a checkpoint belongs to). Throws InputError if it
/// cannot be read.
std::uint64_t sceneFileHash(const std::filesystem::path& file);

class CheckpointWriter
{
  public:
    /// Opens `path`.tmp; throws OutputError if it cannot.
    CheckpointWriter(std::filesystem::path path, CheckpointEngine engine, std::uint64_t sceneHash);
    ~CheckpointWriter(); // without commit(): closes and removes the temporary file
    CheckpointWriter(const CheckpointWriter&) = delete;
    CheckpointWriter& operator=(const CheckpointWriter&) = delete;

    /// One record of `count` elements of `size` bytes at `data`.
    void bytes(const char (&tag)[5], const void* data, std::uint32_t size, std::uint64_t count);
    template <class T> void array(const char (&tag)[5], const std::vector<T>& values)
    {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes(tag, values.data(), sizeof(T), values.size());
    }
    template <class T> void value(const char (&tag)[5], const T& v)
    {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes(tag, &v, sizeof(T), 1);
    }
    void outputs(const CheckpointOutputs& o)
    {
        array("frmT", o.frameTimes);
        array("csvB", o.fileBytes);
        value("tOrg", o.timeOrigin);
    }
    /// Writes the trailer, flushes, fsyncs, closes and renames; throws OutputError on any failure.
    void commit();

    /// The checksum step: folds `n` bytes into `hash` (8-byte words, then the tail bytes).
    static std::uint64_t mix(std::uint64_t hash, const void* data, std::size_t n);

  private:
    void write(const void* data, std::size_t n);

    std::filesystem::path path_, temporary_;
    std::FILE* file_ = nullptr;
    std::uint64_t payloadBytes_ = 0, checksum_;
};

class CheckpointReader
{
  public:
    /// Opens and checks the header and trailer: magic, byte order, version, engine, scene hash and
    /// size. Throws InputError with a one-line reason naming the file.
    CheckpointReader(std::filesystem::path path, CheckpointEngine engine, std::uint64_t sceneHash);
    ~CheckpointReader();
    CheckpointReader(const CheckpointReader&) = delete;
    CheckpointReader& operator=(const CheckpointReader&) = delete;

    /// Reads a record into `values` (resized); throws InputError if its tag, element size or
    /// count does not fit.
    template <class T> void array(const char (&tag)[5], std::vector<T>& values)
    {
        static_assert(std::is_trivially_copyable_v<T>);
        const std::uint64_t count = header(tag, sizeof(T), false, 0);
        values.resize(count);
        read(values.data(), count * sizeof(T));
    }
    /// Reads a record of one element.
    template <class T> void value(const char (&tag)[5], T& v)
    {
        static_assert(std::is_trivially_copyable_v<T>);
        header(tag, sizeof(T), true, 1);
        read(&v, sizeof(T));
    }
    template <class T> T value(const char (&tag)[5])
    {
        T v{};
        value(tag, v);
        return v;
    }
    CheckpointOutputs outputs()
    {
        CheckpointOutputs o;
        array("frmT", o.frameTimes);
        array("csvB", o.fileBytes);
        value("tOrg", o.timeOrigin);
        return o;
    }
    /// Checks that the payload ended and its checksum; call after the last record.
    void finish();

    /// InputError "checkpoint 'FILE': what".
    [[noreturn]] void fail(const std::string& what) const;

  private:
    std::uint64_t header(const char (&tag)[5], std::uint32_t size, bool exact, std::uint64_t count);
    void read(void* data, std::size_t n);

    std::filesystem::path path_;
    std::FILE* file_ = nullptr;
    std::uint64_t payloadBytes_ = 0, consumed_ = 0, expectedChecksum_ = 0, checksum_;
};

} // namespace veridem::io
