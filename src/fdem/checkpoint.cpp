#include "fdem/checkpoint.h"

#include <string>

namespace veridem::fdem
{

/// The private state of the world, for the checkpoint (friend of World). The record order here is
/// the file's.
struct CheckpointAccess
{
    static void write(io::CheckpointWriter& out, const World& w)
    {
        out.value("time", w.time_);
        out.value("step", w.steps_);
        out.value("dets", std::uint64_t(w.detections_));
        out.value("fWrk", w.frictionWork_);
        out.value("dWrk", w.normalDampingWork_);
        const FrictionDiagnostics& d = w.diagnostics_;
        out.value("dgTF", d.tangentialForce);
        out.value("dgCa", d.cap);
        out.value("dgNF", d.normalForce);
        out.value("dgCo", std::uint64_t(d.contacts));
        out.value("dgSl", std::uint64_t(d.sliding));
        out.array("nPos", w.nodes_.position);
        out.array("nVel", w.nodes_.velocity);
        out.array("nFor", w.nodes_.force);
        out.array("nIMa", w.nodes_.inverseMass);
        out.array("nPre", w.nodes_.prescribed);
        out.array("tStr", w.triangles_.stress);
        out.value("lVal", std::uint8_t(w.listsValid_));
        out.array("aNod", w.activeNodes_);
        out.array("aTri", w.activeTriangles_);
        out.value("cVal", std::uint8_t(w.contactsValid_));
        out.value("buff", w.buffer_);
        out.array("pDet", w.positionAtDetection_);
        out.array("cpls", w.contacts_.couples());
        if (!w.joints_.nodes.empty()) // joints come from the scene: present in both or in neither
        {
            const JointStore& j = w.joints_;
            out.array("jDam", j.damage);
            out.array("jOpn", j.opening);
            out.array("jSlp", j.slip);
            out.array("jSgN", j.normalTraction);
            out.array("jSgT", j.shearTraction);
            out.array("jWrk", j.work);
            out.array("jBrT", j.brokenAt);
            out.array("jBrk", j.broken);
            out.value("jNBr", std::uint64_t(w.brokenJoints_));
            out.value("jERl", w.energyReleased_);
        }
    }

    static void read(io::CheckpointReader& in, World& w)
    {
        in.value("time", w.time_);
        in.value("step", w.steps_);
        w.detections_ = static_cast<std::size_t>(in.value<std::uint64_t>("dets"));
        in.value("fWrk", w.frictionWork_);
        in.value("dWrk", w.normalDampingWork_);
        FrictionDiagnostics& d = w.diagnostics_;
        in.value("dgTF", d.tangentialForce);
        in.value("dgCa", d.cap);
        in.value("dgNF", d.normalForce);
        d.contacts = static_cast<std::size_t>(in.value<std::uint64_t>("dgCo"));
        d.sliding = static_cast<std::size_t>(in.value<std::uint64_t>("dgSl"));
        const std::size_t nodes = w.nodes_.size(), triangles = w.triangles_.size();
        sized(in, "nPos", w.nodes_.position, nodes);
        sized(in, "nVel", w.nodes_.velocity, nodes);
        sized(in, "nFor", w.nodes_.force, nodes);
        sized(in, "nIMa", w.nodes_.inverseMass, nodes);
        sized(in, "nPre", w.nodes_.prescribed, nodes);
        sized(in, "tStr", w.triangles_.stress, triangles);
        w.listsValid_ = in.value<std::uint8_t>("lVal") != 0;
        in.array("aNod", w.activeNodes_);
        in.array("aTri", w.activeTriangles_);
        w.contactsValid_ = in.value<std::uint8_t>("cVal") != 0;
        in.value("buff", w.buffer_);
        in.array("pDet", w.positionAtDetection_);
        in.array("cpls", w.contacts_.couples());
        if (!w.joints_.nodes.empty())
        {
            JointStore& j = w.joints_;
            const std::size_t n = j.size();
            sized(in, "jDam", j.damage, n);
            sized(in, "jOpn", j.opening, n);
            sized(in, "jSlp", j.slip, n);
            sized(in, "jSgN", j.normalTraction, n);
            sized(in, "jSgT", j.shearTraction, n);
            sized(in, "jWrk", j.work, n);
            sized(in, "jBrT", j.brokenAt, n);
            sized(in, "jBrk", j.broken, n);
            w.brokenJoints_ = static_cast<std::size_t>(in.value<std::uint64_t>("jNBr"));
            in.value("jERl", w.energyReleased_);
        }
        bool ok = w.positionAtDetection_.size() == w.activeNodes_.size() || !w.contactsValid_;
        for (const auto n : w.activeNodes_)
            ok = ok && n < nodes;
        for (const auto t : w.activeTriangles_)
            ok = ok && t < triangles;
        for (const Couple& c : w.contacts_.couples())
            ok = ok && c.first < triangles && c.second < triangles;
        if (!ok)
            in.fail("is corrupt: its contact or active lists do not fit the scene");
    }

  private:
    template <class T>
    static void sized(io::CheckpointReader& in, const char (&tag)[5], std::vector<T>& values, std::size_t n)
    {
        in.array(tag, values);
        if (values.size() != n)
            in.fail("has " + std::to_string(values.size()) + " elements in record '" + tag + "', the scene " +
                    std::to_string(n) + " (was a mesh file changed?)");
    }
};

void writeCheckpoint(const std::filesystem::path& path, const World& world, std::uint64_t sceneHash,
                     const io::CheckpointOutputs& outputs)
{
    io::CheckpointWriter out(path, io::CheckpointEngine::Fdem2d, sceneHash);
    CheckpointAccess::write(out, world);
    out.outputs(outputs);
    out.commit();
}

io::CheckpointOutputs readCheckpoint(const std::filesystem::path& path, World& world, std::uint64_t sceneHash)
{
    io::CheckpointReader in(path, io::CheckpointEngine::Fdem2d, sceneHash);
    CheckpointAccess::read(in, world);
    io::CheckpointOutputs outputs = in.outputs();
    in.finish();
    return outputs;
}

} // namespace veridem::fdem
