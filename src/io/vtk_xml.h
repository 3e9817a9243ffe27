// DataArray elements of VTK XML files (https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html),
// shared by the 3D particle output and the 2D mesh output. ASCII writes the values inline with
// round-trip precision; binary appends them raw, zlib-compressed in blocks, in the layout of VTK's
// vtkZLibDataCompressor with UInt64 headers ([blocks, block size, last block size, compressed
// sizes...] then the blocks), which ParaView and VTK's own readers read.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>

namespace veridem::io
{

enum class VtkFormat
{
    Ascii,
    Binary,
};

/// "ascii" or "binary".
const char* vtkFormatName(VtkFormat format);

/// With `vtk_format = "auto"`, files of at least this many points are binary.
inline constexpr std::size_t kBinaryVtkFromPoints = 1000;

/// The format of a scene's `vtk_format` choice ("auto", "ascii" or "binary") for `points` points.
VtkFormat chooseVtkFormat(std::string_view choice, std::size_t points);

class VtkXmlArrays
{
  public:
    explicit VtkXmlArrays(VtkFormat format) : format_(format) {}

    /// `type` and version attributes of the <VTKFile> element, e.g. vtkFileOpening("PolyData").
    std::string vtkFileOpening(std::string_view type) const;

    /// One <DataArray>; `count` values (components * tuples). An empty `name` writes none.
    void float64(std::ostream& xml, std::string_view name, int components, const double* data,
                 std::size_t count);
    void int64(std::ostream& xml, std::string_view name, int components, const std::int64_t* data,
               std::size_t count);
    void int32(std::ostream& xml, std::string_view name, int components, const std::int32_t* data,
               std::size_t count);
    void uint8(std::ostream& xml, std::string_view name, int components, const std::uint8_t* data,
               std::size_t count);

    /// Writes the <AppendedData> section (binary) and </VTKFile>; call after the dataset's end tag.
    void finish(std::ostream& xml);

  private:
    template <class T>
    void array(std::ostream& xml, const char* type, std::string_view name, int components, const T* data,
               std::size_t count);

    VtkFormat format_;
    std::string appended_; // binary: the compressed arrays, in order
};

} // namespace veridem::io
