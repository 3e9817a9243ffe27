// ParaView collections (.pvd) and the DataArray elements of VTK XML files
// (https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html), shared by the 3D particle output and
// the 2D mesh output. ASCII writes the values inline with round-trip precision; binary appends them raw,
// zlib-compressed in blocks, in the layout of VTK's vtkZLibDataCompressor with UInt64 headers ([blocks, block
// size, last block size, compressed sizes...] then the blocks), which ParaView and VTK's own readers read.
#pragma once

#include "io/output_file.h"

#include <cstdint>
#include <filesystem>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace veridem::io
{

enum class VtkFormat
{
    Ascii,
    Binary,
};

/// Writes the ParaView collection `path` (.pvd) atomically: one DataSet for each frame k whose
/// listed[k] is true, at time times[k] [s], file fileOf(k) (relative to the .pvd).
template <class FileOf>
void writePvdCollection(const std::filesystem::path& path, const std::vector<double>& times,
                        const std::vector<bool>& listed, const FileOf& fileOf)
{
    AtomicFile file(path);
    std::string text =
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
    for (std::size_t k = 0; k < times.size(); ++k)
    {
        if (!listed[k])
            continue;
        text += "<DataSet timestep=\"";
        appendNumber(text, times[k]);
        text += "\" file=\"";
        text += fileOf(k);
        text += "\"/>\n";
    }
    text += "</Collection>\n</VTKFile>\n";
    file.stream() << text;
    file.commit();
}

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
