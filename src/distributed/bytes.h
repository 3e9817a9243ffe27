// Values to and from the byte buffers of an exchange (distributed/collective.h), in the machine's own
// byte order and number format (the ranks share one).
#pragma once

#include "core/error.h"
#include "core/vec3.h"

#include <cstddef>
#include <cstring>
#include <span>
#include <string>
#include <vector>

namespace veridem::distributed
{

struct ByteWriter
{
    std::vector<std::byte>& out;
    template <class T> void put(const T& value)
    {
        const auto* bytes = reinterpret_cast<const std::byte*>(&value);
        out.insert(out.end(), bytes, bytes + sizeof value);
    }
    void put(const Vec3& v)
    {
        put(v.x);
        put(v.y);
        put(v.z);
    }
};

struct ByteReader
{
    std::span<const std::byte> in;
    std::size_t at = 0;
    template <class T> T get()
    {
        if (at + sizeof(T) > in.size())
            throw SimulationError("MPI exchange: a message of " + std::to_string(in.size()) +
                                  " bytes ends inside a record");
        T value;
        std::memcpy(&value, in.data() + at, sizeof value);
        at += sizeof value;
        return value;
    }
    Vec3 vec3()
    {
        const Real x = get<Real>(), y = get<Real>(), z = get<Real>();
        return {x, y, z};
    }
    bool done() const { return at == in.size(); }
};

} // namespace veridem::distributed
