// Verification cases written in Python against the public API only (docs/python.md): the runner
// starts Debian's /usr/bin/python3 on the script with the built module on PYTHONPATH and reads back
// one line per quantity:
//   quantity<TAB>name<TAB>unit<TAB>expected<TAB>measured<TAB>tolerance<TAB>relative|absolute<TAB>why
// A script that fails, or a module that was not built, fails the case with its output as a note.
#include "case.h"

#include <array>
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>

namespace veridem::verify
{
namespace
{

std::vector<std::string> split(const std::string& line, char separator)
{
    std::vector<std::string> parts;
    std::stringstream s(line);
    for (std::string part; std::getline(s, part, separator);)
        parts.push_back(part);
    return parts;
}

CaseResult runScript(const std::string& script)
{
    const std::string command = VERIDEM_PYTHON_PRELOAD " PYTHONPATH=\"" VERIDEM_PYTHON_DIR
                                                       "\" PYTHONDONTWRITEBYTECODE=1 /usr/bin/python3 \"" +
                                std::string(VERIDEM_SOURCE_DIR) + "/verification/python/" + script +
                                "\" 2>&1";
    CaseResult r;
    std::string output;
    {
        std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
        if (!pipe)
            throw std::runtime_error("cannot start " + command);
        std::array<char, 4096> buffer;
        while (std::fgets(buffer.data(), int(buffer.size()), pipe.get()))
            output += buffer.data();
        const int status = pclose(pipe.release());
        if (status != 0)
        {
            r.notes.push_back("the script failed (status " + std::to_string(status) +
                              "; is the Python module built? cmake --build --preset release --target "
                              "veridem_python): " +
                              output);
            r.quantities.push_back(absoluteQuantity("script exit status", "", 0, status, 0, "it must run"));
            return r;
        }
    }
    for (const std::string& line : split(output, '\n'))
    {
        const std::vector<std::string> f = split(line, '\t');
        if (f.size() == 8 && f[0] == "quantity")
            r.quantities.push_back((f[6] == "absolute" ? absoluteQuantity : relativeQuantity)(
                f[1], f[2], std::stod(f[3]), std::stod(f[4]), std::stod(f[5]), f[7]));
        else if (!line.empty())
            r.notes.push_back(line);
    }
    if (r.quantities.empty())
        r.quantities.push_back(
            absoluteQuantity("quantities reported", "", 1, 0, 0, "the script must report"));
    return r;
}

} // namespace

VERIDEM_CASE(
    {.name = "python_restitution",
     .summary = "a ball's restitution against e for three e, written in Python on the public API",
     .reference = "damped linear oscillator (docs/models.md); verification/python/restitution_from_python.py",
     .labels = {"dem", "quick", "python"},
     .run = [](const CaseContext&) { return runScript("restitution_from_python.py"); }});

} // namespace veridem::verify
