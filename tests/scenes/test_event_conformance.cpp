// The rupture events hold at every drive, friction law and lattice (theory.md §5a): each run of the
// matrix is judged against its own loading curve and slip history, read back from its tables and
// recomputed here, independently of the observer:
//
//   - every drop of F_S/F_N by at least 3 % of F_N is matched by exactly one finished global slip
//     starting after the previous drop's lowest point and within 5 % of the drop's peak F_S/F_N;
//   - no global slip without a drop;
//   - every precursor reaches as far as the interface slipped, within one block: no more than one
//     block beyond its farthest ruptured block slipped fast, while the event ruptured, by more than
//     its contact takes elastically (the law's characteristic slip), and that block or the one
//     before slipped at least min_slip;
//   - and the run's own check (precursors_summary.yaml) says the same.
//
// The matrix crosses the five shipped laws, drives from the paper's 1e-4 m/s to 3e-2 m/s, the
// 41 x 9, 81 x 17 and (short) 161 x 33 lattices, theta = -0.833, 0 and 0.833, and seeds. The cases
// that failed before theory.md §5a's definition are in the part every test run does
// (EventConformance.*); the whole matrix (EventConformanceMatrix.*) takes about seven minutes on
// two cores and is built with -DFRICTIONLAB_EVENT_MATRIX=ON (`ctest -R EventConformanceMatrix -j 2`).
#include <algorithm>
#include <cmath>
#include <limits>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "cli.hpp"
#include "csv.hpp"

namespace frictionlab {
namespace {

namespace fs = std::filesystem;

const std::string configs = std::string(FRICTIONLAB_SOURCE_DIR) + "/configs/";

struct Case {
    std::string law;  // the friction law's type
    double velocity;  // m/s
    int nx = 41, nz = 9;
    double theta = 0;
    int seed = 1;
    double extra_ratio = 0.2;  // F_S/F_N the run goes on past F_S/F_N 0.55, for the global slips to come
};

std::string name(const Case& c) {
    std::string v = fmt::format("{:g}", c.velocity);
    for (char& ch : v)
        if (ch == '-' || ch == '.') ch = '_';
    std::string t = fmt::format("{:g}", c.theta);
    for (char& ch : t)
        if (ch == '-')
            ch = 'm';
        else if (ch == '.')
            ch = '_';
    return fmt::format("{}_v{}_{}x{}_theta{}_seed{}", c.law, v, c.nx, c.nz, t, c.seed);
}

/// The shipped scene of each law: the headline for Li et al.'s, configs/peer_laws/ for the others.
std::string scene_of(const std::string& law) {
    if (law == "three_state_junctions") return configs + "headline.yaml";
    return configs + "peer_laws/maegawa_" + law + ".yaml";
}

/// A time step every scheme of the shipped scenes keeps stable on the lattice (the limit falls as
/// the spacing squared: theory.md §1a; at 81 x 17 imex_euler's is 9.77e-8 s).
double time_step(const Case& c) { return c.nx <= 41 ? 2e-7 : c.nx <= 81 ? 8e-8 : 3e-8; }

/// Loading long enough to pass the laws' first global slips (F_S/F_N 0.2-0.45 at K_S V = 0.8e6 V N/s
/// on 400 N) by a margin: F_S/F_N 0.55, and `extra_ratio` more.
double loading_time(const Case& c) { return (0.55 + c.extra_ratio) * 400 / (0.8e6 * c.velocity); }

struct Run {
    testing::Columns curve, events, slip;
    testing::Columns pinned;  // interface_pinned_fraction.csv; empty for a law without junctions
    YAML::Node summary;
    double loading_start = 0;
};

Run run(const Case& c) {
    const auto dir = testing::work_directory() / name(c);
    fs::create_directories(dir);
    const std::string args = fmt::format(
        "run -q -o out {} --set loaders[2].velocity={:g} --set stages[1].duration={:g} --set bulk.nx={} --set "
        "bulk.nz={} --set loaders[1].theta={:g} --set seed={} --set integrator.dt={:g} --set 'observers=[{{type: "
        "loading_curve, every: 1.0e-5}}, {{type: precursors, every: 1.0e-5}}, {{type: interface_history, every: "
        "{:g}}}]'",
        scene_of(c.law), c.velocity, loading_time(c), c.nx, c.nz, c.theta, c.seed, time_step(c),
        c.velocity >= 1e-3 ? 1e-5 : 1e-4);
    const auto r = testing::frictionlab(args, dir);
    EXPECT_EQ(r.code, 0) << args << "\n" << r.output;
    Run out;
    out.curve = testing::read_csv(dir / "out" / "loading_curve.csv");
    out.events = testing::read_csv(dir / "out" / "precursors.csv");
    out.summary = YAML::LoadFile((dir / "out" / "precursors_summary.yaml").string());
    out.loading_start = YAML::LoadFile((dir / "out" / "run.yaml").string())["loading_start"].as<double>();
    out.slip = testing::read_csv(dir / "out" / "interface_slip.csv");
    if (fs::exists(dir / "out" / "interface_pinned_fraction.csv"))
        out.pinned = testing::read_csv(dir / "out" / "interface_pinned_fraction.csv");
    return out;
}

struct Drop {
    double peak_time, peak_ratio, trough_time;
    bool major;  // a drop: fell by the threshold; smaller falls go beyond the ringing only
};

/// The falls of F_S/F_N during loading by more than a third of `threshold` (the ringing of a slip),
/// each from its peak to its lowest point before F_S/F_N rises a third of the threshold again; those
/// by at least `threshold` are drops.
std::vector<Drop> falls_of(const Run& r, double threshold = 0.03) {
    const auto& t = r.curve.at("time");
    const auto& ratio = r.curve.at("driving_force_over_normal_load");
    std::vector<Drop> out;
    std::size_t peak = 0, trough = 0;
    bool falling = false;
    const auto close = [&] {
        out.push_back({t[peak], ratio[peak], t[trough], ratio[peak] - ratio[trough] >= threshold});
    };
    for (std::size_t k = 0; k < t.size(); ++k) {
        if (t[k] < r.loading_start) {
            peak = k + 1;
            continue;
        }
        if (falling) {
            if (ratio[k] < ratio[trough]) trough = k;
            if (ratio[k] - ratio[trough] >= threshold / 3 || k + 1 == t.size()) {
                close();
                falling = false;
                peak = k;
            }
        } else if (ratio[k] > ratio[peak]) {
            peak = k;
        } else if (ratio[peak] - ratio[k] >= threshold / 3) {
            falling = true;
            trough = k;
            if (k + 1 == t.size()) close();
        }
    }
    return out;
}

void expect_conformance(const Case& c) {
    const Run r = run(c);
    const auto& e = r.events;
    ASSERT_TRUE(e.count("global")) << "no precursors table";
    const std::size_t n_events = e.at("global").size();
    const auto falls = falls_of(r);
    const double spacing = 0.1 / (c.nx - 1);
    using std::isnan;

    // Every drop: exactly one finished global slip in its window (after the fall before), starting
    // near its peak. A smaller fall may hold a global slip that released less load.
    std::vector<char> in_window(n_events, 0);
    double previous_trough = -1;
    int globals = 0;
    for (std::size_t d = 0; d < falls.size(); ++d) {
        std::vector<std::size_t> matched;
        for (std::size_t k = 0; k < n_events; ++k)
            if (e.at("global")[k] > 0.5 && e.at("t_start")[k] > previous_trough &&
                e.at("t_start")[k] <= falls[d].trough_time)
                matched.push_back(k), in_window[k] = 1;
        previous_trough = falls[d].trough_time;
        if (!falls[d].major) continue;
        const bool last = d + 1 == falls.size();
        EXPECT_EQ(matched.size(), 1u) << "drop " << d << " from F_S/F_N " << falls[d].peak_ratio
                                      << " at t = " << falls[d].peak_time;
        if (matched.size() != 1) continue;
        const std::size_t g = matched[0];
        ++globals;
        if (!last) {
            EXPECT_EQ(e.at("finished")[g], 1) << "the global slip of drop " << d << " never ended";
        }
        EXPECT_NEAR(e.at("force_ratio")[g], falls[d].peak_ratio, 0.05 * falls[d].peak_ratio)
            << "the global slip of drop " << d << " starts far from its peak";
    }
    EXPECT_GE(globals, 1) << "no global slip: the run is too short";
    for (std::size_t k = 0; k < n_events; ++k)
        if (e.at("global")[k] > 0.5 && e.at("finished")[k] > 0.5) {
            EXPECT_TRUE(in_window[k]) << "global slip event " << k << " at F_S/F_N " << e.at("force_ratio")[k]
                                      << " without a fall of F_S/F_N";
        }

    // Every finished precursor against the slip history: no more than one block beyond its farthest
    // ruptured block slipped fast (its mean rate over rate_window above quiet_speed) by more than the
    // law's characteristic slip, and its farthest ruptured block or the one before slipped min_slip.
    const YAML::Node settings = r.summary["settings"];
    const auto setting = [&](const char* key) {
        return settings[key].IsNull() ? std::numeric_limits<double>::quiet_NaN() : settings[key].as<double>();
    };
    const double min_slip = setting("min_slip"), characteristic = setting("characteristic_slip");
    const double quiet_time = setting("quiet_time"), window = setting("rate_window");
    const double quiet_speed = setting("quiet_speed"), ruptured_fraction = setting("ruptured_fraction");
    const auto& t = r.slip.at("time");
    const auto column = [&](const testing::Columns& table, std::size_t block) -> const std::vector<double>* {
        const auto it = table.find(fmt::format("block_{}", block));
        return it == table.end() ? nullptr : &it->second;
    };
    const auto rate_above_quiet = [&](const std::vector<double>& u, std::size_t row) {
        std::size_t ref = row;
        while (ref > 0 && t[row] - t[ref] < window * (1 - 1e-9)) --ref;
        return row > ref && (u[row] - u[ref]) / (t[row] - t[ref]) > quiet_speed;
    };
    // With junctions: whether a block of blocks [first, last] ruptures at a row, its contact broken
    // (more than ruptured_fraction of its junctions not pinned) and slipping faster than quiet_speed.
    const auto ruptures_at = [&](std::size_t row, std::size_t first, std::size_t last) {
        for (std::size_t block = first; block <= last; ++block) {
            const auto* u = column(r.slip, block);
            const auto* pinned = column(r.pinned, block);
            if (u && pinned && 1 - (*pinned)[row] > ruptured_fraction && rate_above_quiet(*u, row)) return true;
        }
        return false;
    };
    for (std::size_t k = 0; k < n_events; ++k) {
        if (e.at("global")[k] > 0.5 || e.at("finished")[k] < 0.5) continue;
        const double from = e.at("t_start")[k], to = e.at("t_end")[k];
        // At 1e-4 m/s the history is ten times coarser than the observer's cadence (a run of 2.75 s):
        // slip between two of its rows is taken as linear in time, so that only the part of a row's
        // slip within the event counts, and the tip's slip is read when the event ended (quiet_time
        // after its last rupture), as the observer reads it.
        std::size_t a = 0, b = 0;
        while (a + 1 < t.size() && t[a + 1] < from) ++a;
        while (b + 1 < t.size() && t[b] < to) ++b;
        const auto at = [&](const std::vector<double>& u, double time) {
            std::size_t row = 0;
            while (row + 2 < t.size() && t[row + 1] < time) ++row;
            const double w = std::clamp((time - t[row]) / (t[row + 1] - t[row]), 0.0, 1.0);
            return u[row] + w * (u[row + 1] - u[row]);
        };
        // The event's slip is what the interface slips while the event ruptures. Its start may be a
        // nucleation merged into it (theory.md §5a) milliseconds before its rupture, while the
        // interface creeps at the drive's speed, faster than quiet_speed but not rupturing: with
        // junctions, a row's slip counts only while a block of the event's extent ruptures at
        // either end of the row's interval. (A law without junctions' tables do not say.)
        const auto first = static_cast<std::size_t>(std::lround(e.at("min_ruptured_x")[k] / spacing));
        const auto tip = static_cast<std::size_t>(std::lround(e.at("max_ruptured_x")[k] / spacing));
        std::vector<char> rupturing(t.size(), 1);
        if (!r.pinned.empty())
            for (std::size_t row = a + 1; row <= b; ++row)
                rupturing[row] = ruptures_at(row, first, tip) || ruptures_at(row - 1, first, tip);
        std::vector<double> fast, total;
        for (std::size_t i = 0;; ++i) {
            const auto* slip = column(r.slip, i);
            if (!slip) break;
            const auto& u = *slip;
            double sum = 0;
            for (std::size_t row = a + 1; row <= b; ++row) {
                const double within = std::max(0.0, std::min(t[row], to) - std::max(t[row - 1], from));
                if (rupturing[row] && rate_above_quiet(u, row))
                    sum += (u[row] - u[row - 1]) * within / (t[row] - t[row - 1]);
            }
            fast.push_back(sum);
            total.push_back(at(u, to + quiet_time) - u[a]);  // a block's contact holds it until `from`
        }
        double largest = 0;
        for (double f : fast) largest = std::max(largest, f);
        const double slipped = std::isnan(characteristic) ? 0.5 * largest : characteristic;
        // Up to a block that ruptured in another event meanwhile: that slip is the other's.
        const auto others = [&](std::size_t block) {
            for (std::size_t o = 0; o < n_events; ++o)
                if (o != k && e.at("t_start")[o] <= to && e.at("t_end")[o] >= from &&
                    block * spacing >= e.at("min_ruptured_x")[o] - 1e-12 &&
                    block * spacing <= e.at("max_ruptured_x")[o] + 1e-12)
                    return true;
            return false;
        };
        std::size_t last = tip;
        while (last + 1 < fast.size() && fast[last + 1] > slipped && !others(last + 1)) ++last;
        EXPECT_LE(last, tip + 1) << "precursor " << k << " (F_S/F_N " << e.at("force_ratio")[k]
                                 << ") stops short of the slip: it reaches block " << tip
                                 << ", the interface slipped to " << last;
        const double tip_slip = std::max(total[tip], tip > 0 ? total[tip - 1] : 0.0);
        EXPECT_GE(tip_slip, min_slip) << "precursor " << k << " reaches block " << tip << ", which hardly slipped";
    }
    EXPECT_EQ(r.summary["event_check"]["verdict"].as<std::string>(), "agree")
        << YAML::Dump(r.summary["event_check"]["problems"]);
}

class EventConformance : public ::testing::TestWithParam<Case> {};
TEST_P(EventConformance, GlobalSlipsMatchTheDropsAndPrecursorsTheSlip) { expect_conformance(GetParam()); }

// The cases that failed before (theory.md §5a): the tutorial's seed sweep at 10x the headline's
// drive (seed 1 merged its precursors and global slip into one 14.9 ms "global slip" from F_S/F_N
// 0.18), slip weakening at that drive (a "global slip" at 0.0127, never finished), the headline at
// 30x (one unfinished 8 ms event from 0.18), two-state junctions at 10x (global slips 5 ms before
// their drops), and the other laws and loads at 10x.
INSTANTIATE_TEST_SUITE_P(FailedBefore, EventConformance,
                         ::testing::Values(Case{"three_state_junctions", 1e-2, 41, 9, 0, 1},
                                           Case{"three_state_junctions", 1e-2, 41, 9, 0, 2},
                                           Case{"three_state_junctions", 1e-2, 41, 9, 0, 3},
                                           Case{"three_state_junctions", 3e-2}, Case{"slip_weakening", 1e-2},
                                           Case{"two_state_junctions", 1e-2}, Case{"coulomb", 1e-2},
                                           Case{"rate_state", 1e-2}, Case{"three_state_junctions", 1e-2, 41, 9, 0.833},
                                           Case{"three_state_junctions", 1e-2, 41, 9, -0.833}),
                         [](const auto& info) { return name(info.param); });

#ifdef FRICTIONLAB_EVENT_MATRIX
class EventConformanceMatrix : public ::testing::TestWithParam<Case> {};
TEST_P(EventConformanceMatrix, GlobalSlipsMatchTheDropsAndPrecursorsTheSlip) { expect_conformance(GetParam()); }

std::vector<Case> matrix() {
    std::vector<Case> cases;
    const std::vector<std::string> laws{"three_state_junctions", "two_state_junctions", "slip_weakening", "coulomb",
                                        "rate_state"};
    // Every law at every drive, 41 x 9, theta 0, two seeds (the deterministic laws: one).
    for (const auto& law : laws)
        for (const double v : {1e-4, 1e-3, 1e-2, 3e-2})
            for (const int seed : {1, 2}) {
                if (seed == 2 && (law == "slip_weakening" || law == "coulomb" || law == "rate_state")) continue;
                cases.push_back({law, v, 41, 9, 0, seed, v >= 1e-2 ? 0.2 : 0.0});
            }
    // Non-uniform load both ways, for the two junction laws, at the headline's drive and 10x.
    for (const auto& law : {"three_state_junctions", "two_state_junctions"})
        for (const double v : {1e-3, 1e-2})
            for (const double theta : {-0.833, 0.833}) cases.push_back({law, v, 41, 9, theta, 1});
    // Finer lattices: every law on 81 x 17 at 10x; Li et al.'s law at 81 x 17 and 161 x 33 (short: 30x).
    for (const auto& law : laws) cases.push_back({law, 1e-2, 81, 17, 0, 1});
    for (const double theta : {-0.833, 0.0, 0.833}) cases.push_back({"three_state_junctions", 3e-2, 161, 33, theta, 1});
    cases.push_back({"three_state_junctions", 1e-3, 81, 17, 0, 1});
    return cases;
}

INSTANTIATE_TEST_SUITE_P(Matrix, EventConformanceMatrix, ::testing::ValuesIn(matrix()),
                         [](const auto& info) { return name(info.param); });
#endif

}  // namespace
}  // namespace frictionlab
