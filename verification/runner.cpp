#include "runner.h"

#include "core/error.h"
#include "distributed/collective.h"
#include "exec/task_sharing.h"
#include "exec/thread_pool.h"
#include "sweep.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <mutex>
#include <numeric>
#include <sstream>
#include <thread>

namespace veridem::verify
{

namespace
{

std::string jsonEscape(const std::string& s)
{
    std::string out;
    for (char c : s)
    {
        if (c == '"' || c == '\\')
            out += '\\';
        if (c == '\n')
        {
            out += "\\n";
            continue;
        }
        out += c;
    }
    return out;
}

std::string jsonNumber(double v)
{
    if (!std::isfinite(v))
        return "null";
    std::ostringstream s;
    s << std::setprecision(17) << v;
    return s.str();
}

bool selected(const Case& c, const RunRequest& r)
{
    if (!r.names.empty())
        return std::find(r.names.begin(), r.names.end(), c.name) != r.names.end();
    if (r.labels.empty())
        return true;
    for (const auto& l : r.labels)
        if (std::find(c.labels.begin(), c.labels.end(), l) != c.labels.end())
            return true;
    return false;
}

void writeSeries(const std::filesystem::path& dir, const Series& s)
{
    std::error_code failed;
    std::filesystem::create_directories(dir, failed);
    std::ofstream out(dir / (s.name + ".csv"));
    if (failed || !out)
        throw InputError("cannot write the series '" + (dir / (s.name + ".csv")).string() + "'" +
                         (failed ? ": " + failed.message() : std::string()));
    for (std::size_t i = 0; i < s.columns.size(); ++i)
        out << (i ? "," : "") << s.columns[i];
    out << "\n" << std::setprecision(12);
    for (const auto& row : s.rows)
    {
        for (std::size_t i = 0; i < row.size(); ++i)
            out << (i ? "," : "") << row[i];
        out << "\n";
    }
}

void printRow(const std::string& caseName, const Quantity& q)
{
    std::printf("%-30s %-26s %14.7g %14.7g %10.3e %10.3e%s %s\n", caseName.c_str(),
                (q.name + (q.unit.empty() ? "" : " [" + q.unit + "]")).c_str(), q.expected, q.measured,
                q.error(), q.tolerance, q.relative ? "r" : "a", q.passed() ? "PASS" : "FAIL");
}

} // namespace

void listCases()
{
    for (const auto& c : registry())
    {
        std::string labels;
        for (const auto& l : c.labels)
            labels += (labels.empty() ? "" : ",") + l;
        std::printf("%-32s %-22s %s\n", c.name.c_str(), labels.c_str(), c.summary.c_str());
    }
}

int runCases(const RunRequest& request)
{
    for (const auto& n : request.names)
    {
        const auto& cases = registry();
        if (std::none_of(cases.begin(), cases.end(), [&](const Case& c) { return c.name == n; }))
        {
            std::string nearest;
            for (const auto& c : cases)
                if (c.name.find(n) != std::string::npos || n.find(c.name) != std::string::npos)
                    nearest = c.name;
            throw InputError("unknown verification case '" + n + "'" +
                             (nearest.empty() ? "" : " (did you mean '" + nearest + "'?)") +
                             "; `veridem verify --list` shows them all");
        }
    }

    // The output directory is made before any case runs, so that a path that cannot hold it is
    // an error now, not after minutes of cases (and not on the reporting thread while workers run).
    if (request.seriesDir)
    {
        std::error_code failed;
        std::filesystem::create_directories(*request.seriesDir, failed);
        if (failed)
            throw InputError("cannot create the output directory '" + *request.seriesDir +
                             "': " + failed.message());
    }

    const bool onRanks = request.ranks && request.ranks->size() > 1;
    const auto runsOnRanks = [](const Case& c)
    { return std::find(c.labels.begin(), c.labels.end(), "ranks") != c.labels.end(); };
    std::vector<const Case*> chosen;
    std::size_t leftOut = 0; // (on several ranks: the selected cases that run in one process only)
    for (const auto& c : registry())
        if (selected(c, request))
        {
            if (onRanks && !runsOnRanks(c))
            {
                if (!request.names.empty())
                    throw InputError("verification case '" + c.name +
                                     "' runs in one process only (it steps its world itself); under "
                                     "mpirun the cases labelled 'ranks' run (`veridem verify --list` shows "
                                     "each case's labels)");
                ++leftOut;
                continue;
            }
            chosen.push_back(&c);
        }
    if (onRanks && chosen.empty())
        throw InputError("none of the selected verification cases runs on several ranks; the cases "
                         "labelled 'ranks' do");
    if (leftOut > 0)
        std::printf("%zu of the selected cases run in one process only and are left out on %d ranks\n",
                    leftOut, request.ranks->size());
    struct Outcome
    {
        const Case* c;
        CaseResult result;
        std::string error;
    };
    std::vector<Outcome> outcomes(chosen.size());
    // Workers (one per core, or --jobs) each run one case at a time; a case that splits its work
    // into runs (CaseContext::forEach) shares them with the other workers, which take a pending run
    // before they start a new case. On several ranks: none (the cases run on this thread, which
    // alone makes MPI calls).
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    const std::size_t jobs =
        onRanks ? 0 : (request.jobs > 0 ? static_cast<std::size_t>(request.jobs) : cores);
    exec::TaskSharing sharing;
    const CaseContext context{.showProgress = request.showProgress,
                              .ranks = onRanks ? request.ranks : nullptr,
                              .tasks = jobs > 1 ? &sharing : nullptr};
    const auto runOne = [&](std::size_t k)
    {
        Outcome o{chosen[k], {}, {}};
        const auto start = std::chrono::steady_clock::now();
        try
        {
            o.result = request.dtSweep ? runWithSweep(*chosen[k], context) : chosen[k]->run(context);
        }
        catch (const std::exception& e)
        {
            o.error = e.what();
        }
        catch (...) // (on a worker thread an escaping exception would end the program)
        {
            o.error = "an exception that is not a std::exception";
        }
        o.result.wallSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return o;
    };

    // Workers start the long cases (labelled bulk, then slow) first, the rest in registry order, so
    // that no long run is left for the end; this thread reports them in registry order.
    const auto rank = [](const Case& c)
    {
        const auto has = [&](const char* l)
        { return std::find(c.labels.begin(), c.labels.end(), l) != c.labels.end(); };
        return has("bulk") ? 0 : has("slow") ? 1 : 2;
    };
    std::vector<std::size_t> startOrder(chosen.size());
    std::iota(startOrder.begin(), startOrder.end(), std::size_t(0));
    std::stable_sort(startOrder.begin(), startOrder.end(),
                     [&](std::size_t a, std::size_t b) { return rank(*chosen[a]) < rank(*chosen[b]); });
    std::mutex mutex;
    std::condition_variable finished;
    std::vector<char> done(chosen.size(), 0);
    std::atomic<std::size_t> next{0};
    // Starts the next case not yet started and returns when it has finished; false if none is left.
    const auto startNext = [&]
    {
        const std::size_t n = next++;
        if (n >= startOrder.size())
            return false;
        const std::size_t k = startOrder[n];
        Outcome o = runOne(k);
        const std::lock_guard<std::mutex> lock(mutex);
        outcomes[k] = std::move(o);
        done[k] = 1;
        finished.notify_all();
        return true;
    };
    // A worker waiting for its case's runs on other workers starts another case meanwhile.
    sharing.setIdleWork(startNext);
    const auto worker = [&]
    {
        // One thread per case's loops when cases run side by side: the cores are taken by the
        // other cases.
        const exec::ThreadCountOverride loops(jobs > 1 ? 1 : exec::threads());
        for (;;)
        {
            if (sharing.runPending()) // another case's run first: that case is already running
                continue;
            if (!startNext() && !sharing.waitForTask()) // no case left: help the running ones
                return;
        }
    };
    // Joined on every way out: an exception on this thread (a series that cannot be written) must
    // not destroy running threads, which would end the program; the workers take no further case.
    struct Workers
    {
        std::vector<std::thread> threads;
        std::atomic<std::size_t>& next;
        std::size_t count;
        exec::TaskSharing& sharing;
        ~Workers()
        {
            next = count;
            sharing.close();
            for (auto& t : threads)
                if (t.joinable())
                    t.join();
        }
    } workers{{}, next, chosen.size(), sharing};
    for (std::size_t w = 0; w < jobs; ++w)
        workers.threads.emplace_back(worker);

    std::printf("%-30s %-26s %14s %14s %10s %11s %s\n", "case", "quantity", "theory", "measured", "error",
                "tolerance", "result");
    std::printf("%s\n", std::string(118, '-').c_str());
    std::fflush(stdout);
    for (std::size_t k = 0; k < chosen.size(); ++k)
    {
        if (onRanks)
            outcomes[k] = runOne(k);
        else
        {
            std::unique_lock<std::mutex> lock(mutex);
            finished.wait(lock, [&] { return done[k] != 0; });
        }
        const Outcome& o = outcomes[k];
        const Case& c = *o.c;
        for (const auto& q : o.result.quantities)
            printRow(c.name, q);
        if (!o.error.empty())
            std::printf("%-30s ERROR: %s\n", c.name.c_str(), o.error.c_str());
        else if (o.result.quantities.empty())
            std::printf("%-30s ERROR: the case measured nothing\n", c.name.c_str());
        for (const auto& note : o.result.notes)
            std::printf("%-30s   note: %s\n", "", note.c_str());
        std::printf("%-30s   (%.2f s)\n", "", o.result.wallSeconds);
        std::fflush(stdout);
        if (request.seriesDir)
            for (const auto& s : o.result.series)
                writeSeries(std::filesystem::path(*request.seriesDir) / c.name, s);
    }
    sharing.close();
    for (auto& w : workers.threads)
        w.join();

    int failed = 0;
    for (const auto& o : outcomes)
        failed += (!o.error.empty() || !o.result.passed()) ? 1 : 0;
    std::printf("%s\n", std::string(118, '-').c_str());
    std::printf("%zu cases: %zu passed, %d failed\n", outcomes.size(), outcomes.size() - failed, failed);

    if (request.jsonPath)
    {
        const std::filesystem::path jsonPath(*request.jsonPath);
        if (jsonPath.has_parent_path())
            std::filesystem::create_directories(jsonPath.parent_path());
        std::ofstream out(jsonPath);
        if (!out)
            throw InputError("cannot write JSON to '" + *request.jsonPath + "'");
        out << "{\"cases\":[";
        for (std::size_t k = 0; k < outcomes.size(); ++k)
        {
            const auto& o = outcomes[k];
            out << (k ? "," : "") << "\n{\"name\":\"" << jsonEscape(o.c->name) << "\",\"summary\":\""
                << jsonEscape(o.c->summary) << "\",\"reference\":\"" << jsonEscape(o.c->reference)
                << "\",\"passed\":" << ((o.error.empty() && o.result.passed()) ? "true" : "false")
                << ",\"seconds\":" << jsonNumber(o.result.wallSeconds);
            if (!o.error.empty())
                out << ",\"error\":\"" << jsonEscape(o.error) << "\"";
            out << ",\"notes\":[";
            for (std::size_t n = 0; n < o.result.notes.size(); ++n)
                out << (n ? "," : "") << "\"" << jsonEscape(o.result.notes[n]) << "\"";
            out << "],\"quantities\":[";
            for (std::size_t q = 0; q < o.result.quantities.size(); ++q)
            {
                const auto& v = o.result.quantities[q];
                out << (q ? "," : "") << "{\"name\":\"" << jsonEscape(v.name) << "\",\"unit\":\""
                    << jsonEscape(v.unit) << "\",\"expected\":" << jsonNumber(v.expected)
                    << ",\"measured\":" << jsonNumber(v.measured)
                    << ",\"tolerance\":" << jsonNumber(v.tolerance)
                    << ",\"relative\":" << (v.relative ? "true" : "false")
                    << ",\"error\":" << jsonNumber(v.error())
                    << ",\"passed\":" << (v.passed() ? "true" : "false") << ",\"why\":\"" << jsonEscape(v.why)
                    << "\"}";
            }
            out << "]}";
        }
        out << "\n]}\n";
    }
    return failed == 0 ? 0 : 1;
}

} // namespace veridem::verify
