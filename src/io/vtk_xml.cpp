#include "io/vtk_xml.h"

#include "core/error.h"
#include "io/output_file.h"

#include <bit>
#include <cstring>
#include <vector>
#include <zlib.h>

namespace veridem::io
{

namespace
{
constexpr std::size_t kBlockBytes = 1 << 16; // uncompressed bytes per zlib block (VTK uses 32 KiB)
constexpr int kZlibLevel = 1;                // fastest: doubles of a run compress little more at 9

template <class T> void appendWord(std::string& out, T value)
{
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    out.append(bytes, sizeof(T));
}

/// Appends `size` bytes compressed as VTK's vtkZLibDataCompressor does, with UInt64 headers.
void appendCompressed(std::string& out, const unsigned char* bytes, std::size_t size)
{
    const std::size_t blocks = (size + kBlockBytes - 1) / kBlockBytes;
    std::vector<std::string> compressed(blocks);
    for (std::size_t b = 0; b < blocks; ++b)
    {
        const std::size_t begin = b * kBlockBytes, length = std::min(kBlockBytes, size - begin);
        uLongf bound = compressBound(static_cast<uLong>(length));
        compressed[b].resize(bound);
        if (compress2(reinterpret_cast<Bytef*>(compressed[b].data()), &bound, bytes + begin,
                      static_cast<uLong>(length), kZlibLevel) != Z_OK)
            throw OutputError("zlib could not compress a VTK array");
        compressed[b].resize(bound);
    }
    appendWord<std::uint64_t>(out, blocks);
    appendWord<std::uint64_t>(out, kBlockBytes);
    appendWord<std::uint64_t>(out, size % kBlockBytes); // 0: the last block is full
    for (const auto& c : compressed)
        appendWord<std::uint64_t>(out, c.size());
    for (const auto& c : compressed)
        out += c;
}

void appendValue(std::string& out, double v)
{
    appendNumber(out, v);
}
template <class T> void appendValue(std::string& out, T v)
{
    char buffer[24];
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, static_cast<long long>(v));
    out.append(buffer, r.ptr);
}
} // namespace

const char* vtkFormatName(VtkFormat format)
{
    return format == VtkFormat::Ascii ? "ascii" : "binary";
}

VtkFormat chooseVtkFormat(std::string_view choice, std::size_t points)
{
    if (choice == "ascii")
        return VtkFormat::Ascii;
    if (choice == "binary")
        return VtkFormat::Binary;
    return points >= kBinaryVtkFromPoints ? VtkFormat::Binary : VtkFormat::Ascii;
}

std::string VtkXmlArrays::vtkFileOpening(std::string_view type) const
{
    std::string s =
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"" + std::string(type) + "\" version=\"1.0\" byte_order=\"";
    s += std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
    s += "\" header_type=\"UInt64\"";
    if (format_ == VtkFormat::Binary)
        s += " compressor=\"vtkZLibDataCompressor\"";
    s += ">\n";
    return s;
}

template <class T>
void VtkXmlArrays::array(std::ostream& xml, const char* type, std::string_view name, int components,
                         const T* data, std::size_t count)
{
    xml << "<DataArray type=\"" << type << "\"";
    if (!name.empty())
        xml << " Name=\"" << name << "\"";
    xml << " NumberOfComponents=\"" << components << "\"";
    if (format_ == VtkFormat::Binary)
    {
        xml << " format=\"appended\" offset=\"" << appended_.size() << "\"/>\n";
        appendCompressed(appended_, reinterpret_cast<const unsigned char*>(data), count * sizeof(T));
        return;
    }
    xml << " format=\"ascii\">\n";
    std::string text;
    text.reserve(count * 8 + 1);
    for (std::size_t i = 0; i < count; ++i)
    {
        appendValue(text, data[i]);
        text += (i + 1) % static_cast<std::size_t>(components) == 0 ? '\n' : ' ';
    }
    xml << text << "</DataArray>\n";
}

void VtkXmlArrays::float64(std::ostream& xml, std::string_view name, int components, const double* data,
                           std::size_t count)
{
    array(xml, "Float64", name, components, data, count);
}
void VtkXmlArrays::int64(std::ostream& xml, std::string_view name, int components, const std::int64_t* data,
                         std::size_t count)
{
    array(xml, "Int64", name, components, data, count);
}
void VtkXmlArrays::int32(std::ostream& xml, std::string_view name, int components, const std::int32_t* data,
                         std::size_t count)
{
    array(xml, "Int32", name, components, data, count);
}
void VtkXmlArrays::uint8(std::ostream& xml, std::string_view name, int components, const std::uint8_t* data,
                         std::size_t count)
{
    array(xml, "UInt8", name, components, data, count);
}

void VtkXmlArrays::finish(std::ostream& xml)
{
    if (format_ == VtkFormat::Binary)
    {
        xml << "<AppendedData encoding=\"raw\">\n_";
        xml.write(appended_.data(), static_cast<std::streamsize>(appended_.size()));
        xml << "\n</AppendedData>\n";
    }
    xml << "</VTKFile>\n";
}

} // namespace veridem::io
