// The friction-law swap (share/docs/tutorial.md, "Swap the friction law"): one scene,
// scenes/swap_base.yaml, run by the frictionlab command once per shipped friction law, with only its `friction:` block
// replaced by the law's block (scenes/friction_<law>.yaml). Each run must show its own law's signature in the
// observers' CSV outputs; every other line of the scene is the same. And the headline scene itself,
// configs/headline.yaml, with each shipped law's or bulk model's block swapped in: it runs, or `check`
// names every change still needed at once.
#include <algorithm>
#include <cmath>
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
using testing::Columns;

const fs::path scenes = SWAP_SCENES;

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::stringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

/// Whether a line opens a top-level key (the end of the block before it).
bool top_level(const std::string& line) { return !line.empty() && line[0] != ' ' && line[0] != '#'; }

/// [first, last) lines of the scene's top-level `key:` block (empty at the end if it has none).
std::pair<std::size_t, std::size_t> top_level_block(const std::vector<std::string>& lines, const std::string& key) {
    std::size_t first = 0;
    while (first < lines.size() && lines[first].rfind(key + ":", 0) != 0) ++first;
    if (first == lines.size()) return {first, first};
    std::size_t last = first + 1;
    while (last < lines.size() && !top_level(lines[last])) ++last;
    return {first, last};
}

std::pair<std::size_t, std::size_t> friction_block(const std::vector<std::string>& lines) {
    return top_level_block(lines, "friction");
}

/// The base scene with its top-level `key:` block replaced by `block`; all other lines untouched.
std::string with_block(const std::string& base, const std::string& key, const std::string& block) {
    const auto lines = lines_of(base);
    const auto [first, last] = top_level_block(lines, key);
    std::string out;
    for (std::size_t i = 0; i < first; ++i) out += lines[i] + "\n";
    out += block;
    for (std::size_t i = last; i < lines.size(); ++i) out += lines[i] + "\n";
    return out;
}

std::string with_friction(const std::string& base, const std::string& block) {
    return with_block(base, "friction", block);
}

/// Lines outside the friction block.
std::vector<std::string> outside_friction(const std::string& scene) {
    auto lines = lines_of(scene);
    const auto [first, last] = friction_block(lines);
    lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(first), lines.begin() + static_cast<std::ptrdiff_t>(last));
    return lines;
}

constexpr int blocks = 41;  // interface blocks of swap_base.yaml's 41 x 9 lattice

/// Outputs of one law's run: rupture events and the interface history tables (column block_<i> per
/// interface block).
struct LawRun {
    fs::path out;
    Columns events, velocity, slip, ratio, pinned, curve;
    std::vector<double> block(const Columns& table, int i) const { return table.at("block_" + std::to_string(i)); }
};

/// Writes the base scene with `law`'s friction block, checks that nothing else changed, and runs it
/// (with `overrides`, e.g. another integrator, as --set options).
LawRun run_with(const std::string& law, const std::string& overrides = "") {
    const std::string base = testing::read_text(scenes / "swap_base.yaml");
    const std::string block = testing::read_text(scenes / ("friction_" + law + ".yaml"));
    EXPECT_FALSE(base.empty() || block.empty());
    const std::string variant = with_friction(base, block);
    EXPECT_EQ(outside_friction(variant), outside_friction(base)) << "only the friction block may differ";
    EXPECT_NE(variant.find("  type: " + law + "\n"), std::string::npos) << variant;

    const fs::path dir = testing::work_directory();
    std::ofstream(dir / "scene.yaml") << variant;
    const auto r = testing::frictionlab("run -q scene.yaml" + overrides, dir);
    EXPECT_EQ(r.code, 0) << r.output;
    LawRun run;
    run.out = dir / "swap_out";
    run.events = testing::read_csv(run.out / "precursors.csv");
    run.velocity = testing::read_csv(run.out / "interface_velocity.csv");
    run.slip = testing::read_csv(run.out / "interface_slip.csv");
    run.ratio = testing::read_csv(run.out / "interface_shear_ratio.csv");
    run.curve = testing::read_csv(run.out / "loading_curve.csv");
    if (fs::exists(run.out / "interface_pinned_fraction.csv"))
        run.pinned = testing::read_csv(run.out / "interface_pinned_fraction.csv");
    return run;
}

/// Largest |friction / normal force| over every block and observation.
double largest_ratio(const LawRun& run) {
    double largest = 0;
    for (const auto& [name, values] : run.ratio)
        if (name != "time")
            for (double r : values) largest = std::max(largest, std::abs(r));
    return largest;
}

/// Index of the first global slip among the run's rupture events (their count if none).
std::size_t first_global_slip(const LawRun& run) {
    const auto& global = run.events.at("global");
    return static_cast<std::size_t>(std::find(global.begin(), global.end(), 1.0) - global.begin());
}

/// First row at or after `from` where `pred(row)` holds, or the row count.
template <class Pred>
std::size_t first_row(std::size_t rows, std::size_t from, Pred pred) {
    for (std::size_t k = from; k < rows; ++k)
        if (pred(k)) return k;
    return rows;
}

constexpr double mu_s = 0.4, mu_k = 0.17;  // the laws' blocks in scenes/friction_*.yaml
constexpr double exact = 1e-9;             // the CSV tables keep 10 significant digits

TEST(FrictionSwap, TheTestScenesDifferOnlyInTheFrictionBlock) {
    const std::string base = testing::read_text(scenes / "swap_base.yaml");
    for (const char* law :
         {"coulomb", "slip_weakening", "two_state_junctions", "three_state_junctions", "rate_state"}) {
        const std::string variant =
            with_friction(base, testing::read_text(scenes / (std::string("friction_") + law + ".yaml")));
        EXPECT_EQ(outside_friction(variant), outside_friction(base)) << law;
        EXPECT_EQ(lines_of(variant).size() - lines_of(base).size() + 2,
                  lines_of(testing::read_text(scenes / (std::string("friction_") + law + ".yaml"))).size())
            << law << ": the base scene's block is two lines";
    }
}

/// Amontons-Coulomb: a block is held up to exactly mu_s f_N and slips at exactly mu_k f_N.
TEST(FrictionSwap, CoulombHoldsUpToTheStaticThresholdThenSlipsAtTheKineticOne) {
    const LawRun run = run_with("coulomb");
    // No block ever carries more than mu_s f_N: a stuck spring above it breaks at the commit.
    EXPECT_LE(largest_ratio(run), mu_s * (1 + exact));
    // The driven-edge block loads up to the threshold, then (the first row at the kinetic value)
    // slips at exactly mu_k f_N against its motion.
    const auto r = run.block(run.ratio, 0), v = run.block(run.velocity, 0);
    const std::size_t rows = r.size();
    const std::size_t slipping =
        first_row(rows, 0, [&](std::size_t k) { return std::abs(r[k] + mu_k) < exact * mu_k; });
    ASSERT_LT(slipping, rows) << "block 0 never slipped";
    double peak = 0;
    for (std::size_t k = 0; k < slipping; ++k) peak = std::max(peak, -r[k]);
    EXPECT_GT(peak, 0.99 * mu_s) << "block 0 slipped before reaching mu_s f_N";
    EXPECT_GT(v[slipping], 0.0);
    std::size_t kinetic = 0;
    for (std::size_t k = slipping; k < rows && v[k] > 0; ++k) kinetic += std::abs(r[k] + mu_k) < exact * mu_k;
    EXPECT_GT(kinetic, 3u);
    // The whole interface first slips well below mu_s F_N (Trømborg et al. 2011): the driven edge
    // reaches mu_s f_N first and the front runs into blocks loaded far less, so the macroscopic
    // coefficient is not the local one (0.20 here); it lies between mu_k and mu_s.
    const std::size_t g = first_global_slip(run);
    ASSERT_LT(g, run.events.at("global").size()) << "no global slip";
    EXPECT_GT(run.events.at("force_ratio")[g], mu_k);
    EXPECT_LT(run.events.at("force_ratio")[g], mu_s);
}

/// Slip weakening: while a block slips its strength falls linearly with slip, from mu_s f_N to mu_d f_N
/// over D_c, then stays at mu_d f_N.
TEST(FrictionSwap, SlipWeakeningStrengthFallsLinearlyWithSlipOverDc) {
    const LawRun run = run_with("slip_weakening");
    constexpr double mu_d = mu_k, d_c = 5e-6;  // scenes/friction_slip_weakening.yaml
    EXPECT_LE(largest_ratio(run), mu_s * (1 + exact));
    const auto r = run.block(run.ratio, 0), v = run.block(run.velocity, 0), u = run.block(run.slip, 0);
    const std::size_t rows = r.size();
    // The weakening branch of block 0's first slip: back from the first row at mu_d, while it moved
    // forward and its strength only fell (before it broke, a stuck block's force rose).
    const std::size_t residual =
        first_row(rows, 0, [&](std::size_t k) { return std::abs(r[k] + mu_d) < exact * mu_d; });
    ASSERT_LT(residual, rows) << "block 0 never weakened to mu_d";
    std::size_t start = residual;
    while (start > 1 && v[start - 1] > 0 && -r[start - 1] >= -r[start]) --start;
    // Fit mu(u) on the rows strictly inside the weakening branch: exact slope -(mu_s - mu_d)/D_c.
    std::vector<std::pair<double, double>> points;
    for (std::size_t k = start; k < residual; ++k)
        if (-r[k] < mu_s * (1 - exact) && -r[k] > mu_d * (1 + exact)) points.emplace_back(u[k], -r[k]);
    ASSERT_GE(points.size(), 5u) << "too few observations inside D_c";
    double su = 0, sm = 0, suu = 0, sum = 0;
    for (const auto& [x, y] : points) su += x, sm += y, suu += x * x, sum += x * y;
    const double n = static_cast<double>(points.size());
    const double slope = (n * sum - su * sm) / (n * suu - su * su), intercept = (sm - slope * su) / n;
    EXPECT_NEAR(slope, -(mu_s - mu_d) / d_c, 1e-6 * (mu_s - mu_d) / d_c);
    for (const auto& [x, y] : points) EXPECT_NEAR(y, intercept + slope * x, 1e-8);
    // The branch starts at mu_s: the block broke at the slip where the line meets mu_s.
    const double broke_at = (mu_s - intercept) / slope;
    EXPECT_LE(broke_at, points.front().first);
    EXPECT_GE(broke_at, u[start - 1]);
}

/// Two-state junctions (Thøgersen et al. 2014; Trømborg et al. 2014): each block's N_s = 100 junctions
/// break at mu_s f_N / N_s, slip at mu_d f_N / N_s, and re-pin unloaded after a time t_R drawn from
/// N(0.2 ms, 0.06 ms).
TEST(FrictionSwap, TwoStateJunctionsSlipAtMuDAndRepinAfterTheirSlippingTimes) {
    const LawRun run = run_with("two_state_junctions");
    constexpr double mu_d = mu_k, t_mean = 2e-4, t_sd = 6e-5;  // scenes/friction_two_state_junctions.yaml
    EXPECT_LE(largest_ratio(run), mu_s * (1 + exact));         // every pinned junction holds at most mu_s f_N / N_s
    // A block whose junctions all slip carries exactly mu_d f_N against its motion.
    std::size_t unpinned = 0;
    for (int b = 0; b < blocks; ++b) {
        const auto p = run.block(run.pinned, b), r = run.block(run.ratio, b);
        for (std::size_t k = 0; k < p.size(); ++k) {
            if (p[k] != 0) continue;
            EXPECT_NEAR(std::abs(r[k]), mu_d, exact * mu_d) << "block " << b;
            ++unpinned;
        }
    }
    EXPECT_GT(unpinned, 100u);
    // Block 0's junctions, pinned unloaded together while the load was applied, carry equal forces and
    // break at once. They re-pin one by one: the first after the shortest of 100 draws of t_R, whose
    // expectation is t_mean - 2.5 t_sd (between t_mean - 3.5 t_sd and t_mean - 1.5 t_sd with
    // probability 0.98; the seed is fixed).
    const auto p = run.block(run.pinned, 0), t = run.pinned.at("time");
    const std::size_t rows = p.size();
    const std::size_t broken = first_row(rows, 1, [&](std::size_t k) { return p[k] < 1; });
    ASSERT_LT(broken, rows) << "block 0 never broke";
    EXPECT_EQ(p[broken], 0.0);
    const std::size_t repinned = first_row(rows, broken, [&](std::size_t k) { return p[k] > 0; });
    ASSERT_LT(repinned, rows);
    const double delay = t[repinned] - t[broken], cadence = t[1] - t[0];
    EXPECT_GT(delay, t_mean - 3.5 * t_sd - cadence);
    EXPECT_LT(delay, t_mean - 1.5 * t_sd + cadence);
    // Between slips the interface re-pins: after the first global slip, the pinned fraction of the
    // whole interface (mean over blocks) comes back above 0.95 (a few junctions keep slipping).
    const std::size_t g = first_global_slip(run);
    ASSERT_LT(g, run.events.at("global").size()) << "no global slip";
    const double slip_end = run.events.at("t_end")[g];
    const auto mean_pinned = [&](std::size_t k) {
        double sum = 0;
        for (int b = 0; b < blocks; ++b) sum += run.block(run.pinned, b)[k];
        return sum / blocks;
    };
    const std::size_t after = first_row(rows, 1, [&](std::size_t k) { return t[k] > slip_end; });
    EXPECT_LT(first_row(rows, after, [&](std::size_t k) { return mean_pinned(k) > 0.95; }), rows)
        << "the interface did not re-pin after the first global slip";
}

/// Three-state junctions (Li et al. 2020, Figs. 6 and 7): precursors, rupture events from the driven
/// edge that arrest part-way, longer as the load grows, before the first global slip.
TEST(FrictionSwap, ThreeStateJunctionsShowGrowingPrecursorsBeforeTheFirstGlobalSlip) {
    const LawRun run = run_with("three_state_junctions");
    const auto& extent = run.events.at("extent_over_length");
    const auto& ratio = run.events.at("force_ratio");
    const std::size_t g = first_global_slip(run);
    ASSERT_LT(g, extent.size()) << "no global slip";
    ASSERT_GE(g, 2u) << "fewer than two precursors";
    double longest = 0;
    for (std::size_t k = 0; k < g; ++k) {
        EXPECT_LT(extent[k], 1.0);
        // Within the blocks a front at several hundred m/s crosses between two observations (10 us).
        EXPECT_LE(run.events.at("nucleation_block")[k], 2.0)
            << "precursor " << k << " did not start at the driven edge";
        EXPECT_LT(ratio[k], ratio[g]);
        longest = std::max(longest, extent[k]);
    }
    EXPECT_EQ(extent[g - 1], longest) << "the last precursor is the longest";
    EXPECT_GT(longest, 0.5);
    EXPECT_GT(ratio[g - 1], ratio[0]);
}

/// How much F_S/F_N rose over the observation before time t (the loading curve's cadence is the
/// precursors observer's).
double ratio_rise_before(const LawRun& run, double t) {
    const auto& time = run.curve.at("time");
    const auto& ratio = run.curve.at("driving_force_over_normal_load");
    const auto k = static_cast<std::size_t>(std::lower_bound(time.begin(), time.end(), t) - time.begin());
    return k == 0 || k >= time.size() ? 0.0 : std::abs(ratio[k] - ratio[k - 1]);
}

/// The quasi-static hybrid with every law that describes its quasi-static regime: the stuck loading
/// is crossed in quiet steps (after the transient of the drive's start, which it integrates), and the
/// first rupture event comes as with RK4 at the hybrid's own dynamic step, within what RK4 itself
/// changes when its step is halved: time (and one observation), F_S (and 1e-4 of it, and what the
/// load adds in that one observation: an event starts when its first block's contact broke, as the
/// observer sees it at its cadence), length (and a block). Measured: two-state junctions, whose
/// block's junctions all break within 5 us, break just before an observation with the hybrid and just
/// after it with RK4 (one observation, 2.4e-4 in F_S/F_N); the other laws at the same observation and
/// F_S within 4e-6; slip weakening, which breaks without a force drop, between RK4's two steps.
/// Every law's first event ends 5 to 8 ms into the loading, so the runs stop 12 ms into it.
TEST(FrictionSwap, EveryLawReachesItsFirstEventWithTheQuasiStaticHybridWithinRk4sStepHalving) {
    const auto first_event = [](const LawRun& run, const char* column) { return run.events.at(column).at(0); };
    const std::string through_the_first_event = " --set stages[1].duration=0.012";
    for (const char* law : {"coulomb", "slip_weakening", "two_state_junctions", "three_state_junctions"}) {
        const LawRun rk4 = run_with(law, " --set 'integrator={type: rk4, dt: 2.0e-7}'" + through_the_first_event);
        const LawRun halved = run_with(law, " --set 'integrator={type: rk4, dt: 1.0e-7}'" + through_the_first_event);
        // Without and with creep steps (implicit, ten explicit steps long) in the slow dynamic spans.
        for (const double creep_step : {0.0, 2e-6}) {
            const LawRun hybrid = run_with(law, fmt::format(" --set 'integrator={{type: quasi_static_hybrid, dt: "
                                                            "2.0e-7, creep_step: {}}}'",
                                                            creep_step) +
                                                    through_the_first_event);
            const YAML::Node stats = YAML::LoadFile((hybrid.out / "run.yaml").string())["integrator_statistics"];
            EXPECT_GE(stats["observations_within_spans"].as<double>(), 100) << law << ": no stuck span crossed quietly";
            EXPECT_EQ(stats["creep_steps"].as<double>() > 0, creep_step > 0) << law;
            const double one_observation = ratio_rise_before(rk4, first_event(rk4, "t_start"));
            EXPECT_LT(one_observation, 1e-3) << law << ": the load rises slowly beside the cadence";
            for (const auto& [column, slack] :
                 {std::pair{"t_start", 1.01e-5}, std::pair{"force_ratio", 1e-4 * 0.2 + one_observation},
                  std::pair{"extent_over_length", 1.01 / (blocks - 1)}}) {
                const double a = first_event(rk4, column), b = first_event(halved, column);
                EXPECT_GE(first_event(hybrid, column), std::min(a, b) - slack) << law << " " << column << creep_step;
                EXPECT_LE(first_event(hybrid, column), std::max(a, b) + slack) << law << " " << column << creep_step;
            }
        }
    }
}

/// Rate and state, velocity strengthening (a > b): the slider ends sliding steadily at the driving
/// rate V, and every block's friction is the closed-form steady state
/// mu_ss(V) = a asinh[(V / 2 v0) exp(psi_ss / a)], psi_ss = f0 - b ln(V / v0).
TEST(FrictionSwap, RateStateSlidesSteadilyAtTheClosedFormSteadyFriction) {
    const LawRun run = run_with("rate_state");
    constexpr double a = 0.012, b = 0.008, f0 = 0.2, v0 = 1e-6;  // scenes/friction_rate_state.yaml
    constexpr double V = 0.02;                                   // swap_base.yaml's driving velocity
    const double psi_ss = f0 - b * std::log(V / v0), mu_ss = a * std::asinh(V / (2 * v0) * std::exp(psi_ss / a));
    const std::size_t last = run.ratio.at("time").size() - 1;
    double worst_v = 0, worst_mu = 0;
    for (int i = 0; i < blocks; ++i) {
        worst_v = std::max(worst_v, std::abs(run.block(run.velocity, i)[last] / V - 1));
        worst_mu = std::max(worst_mu, std::abs(-run.block(run.ratio, i)[last] / mu_ss - 1));
    }
    // Steady within the tables' 10 digits (measured: 1.5e-9 and 4e-11 after 30 ms of loading).
    EXPECT_LT(worst_v, 1e-6) << "not sliding steadily at V";
    EXPECT_LT(worst_mu, 1e-8) << "mu_ss(V) = " << mu_ss;
}

/// The headline scene with one observer (an item `  - type: <type>` of `observers:`) taken out.
std::string without_observer(const std::string& scene, const std::string& type) {
    std::string out;
    bool skipping = false;
    for (const auto& line : lines_of(scene)) {
        if (line.rfind("  - ", 0) == 0 || top_level(line)) skipping = line == "  - type: " + type;
        if (!skipping) out += line + "\n";
    }
    return out;
}

/// One swap into configs/headline.yaml: the block, the diagnostics `check` must give all at once (by
/// key path, each naming its fix), and the fixes that then make it pass.
struct HeadlineSwap {
    std::string key, block;
    std::vector<std::pair<std::string, std::string>> errors;  // key path, a phrase of its fix
    std::vector<std::string> observers_to_remove;
    std::string overrides;  // --set options
};

/// Lines of `output` that hold a diagnostic.
std::vector<std::string> diagnostics_of(const std::string& output) {
    std::vector<std::string> out;
    for (const auto& line : lines_of(output))
        if (line.find("error:") != std::string::npos) out.push_back(line);
    return out;
}

void swap_into_headline(const HeadlineSwap& swap) {
    const std::string headline = testing::read_text(HEADLINE_SCENE);
    ASSERT_FALSE(headline.empty());
    std::string variant = with_block(headline, swap.key, swap.block);
    const fs::path dir = testing::work_directory();
    std::ofstream(dir / "scene.yaml") << variant;
    const auto checked = testing::frictionlab("check scene.yaml", dir);
    const std::string what = swap.key + ": " + swap.block;
    if (swap.errors.empty()) {
        EXPECT_EQ(checked.code, 0) << what << checked.output;
        EXPECT_NE(checked.output.find("stage 'settle': stable step"), std::string::npos) << checked.output;
    } else {
        EXPECT_EQ(checked.code, 2) << what << checked.output;
        // Every change needed at once, each diagnostic once, GCC-style with one `error:`, at its
        // place in the scene and naming the fix.
        const auto found = diagnostics_of(checked.output);
        EXPECT_EQ(found.size(), swap.errors.size()) << what << checked.output;
        const std::string count = fmt::format("{} error{} in scene.yaml", found.size(), found.size() == 1 ? "" : "s");
        EXPECT_NE(checked.output.find(count), std::string::npos) << checked.output;
        for (const auto& line : found) {
            EXPECT_EQ(line.find("error:"), line.rfind("error:")) << "one error: prefix: " << line;
            EXPECT_NE(line.rfind("scene.yaml:", 0), std::string::npos) << "file:line:column first: " << line;
        }
        for (const auto& error : swap.errors) {
            const std::string& path = error.first;  // not a structured binding: clang 14 cannot capture one
            const std::string& fix = error.second;
            const bool named = std::any_of(found.begin(), found.end(), [&](const std::string& line) {
                return line.find(": error: " + path + ":") != std::string::npos && line.find(fix) != std::string::npos;
            });
            EXPECT_TRUE(named) << what << ": " << path << " naming '" << fix << "'\n" << checked.output;
        }
        // The fixes named, all of them at once, make the scene pass.
        for (const auto& type : swap.observers_to_remove) variant = without_observer(variant, type);
        std::ofstream(dir / "scene.yaml") << variant;
        const auto fixed = testing::frictionlab("check scene.yaml" + swap.overrides, dir);
        EXPECT_EQ(fixed.code, 0) << what << ", fixed:\n" << variant << fixed.output;
    }
    // And a short run of it: the settling and 2 ms of loading.
    const auto ran =
        testing::frictionlab("run -q scene.yaml --set stages[1].duration=0.002 --set output=out" + swap.overrides, dir);
    EXPECT_EQ(ran.code, 0) << what << ran.output;
    const YAML::Node record = YAML::LoadFile((dir / "out" / "run.yaml").string());
    EXPECT_EQ(record["status"].as<std::string>(), "done") << what;
    const bool counts = swap.block.find("junctions") != std::string::npos || swap.key == "bulk";
    const bool stuck_spring =
        swap.block.find("coulomb") != std::string::npos || swap.block.find("slip_weakening") != std::string::npos;
    EXPECT_EQ(record["resolved_choices"]["observers[1].criterion"]["value"].as<std::string>(),
              counts         ? "pinned_fraction"
              : stuck_spring ? "slipping"
                             : "slip_rate")
        << what;
}

const std::pair<std::string, std::string> contact_area{"observers[2]", "remove this observer"};

TEST(FrictionSwap, TheHeadlineTakesEveryLawByItsFrictionBlockOrCheckNamesEveryFixAtOnce) {
    swap_into_headline({"friction", "friction:\n  type: three_state_junctions\n", {}, {}, ""});
    swap_into_headline({"friction", "friction:\n  type: two_state_junctions\n", {}, {}, ""});
    // Without junctions: the precursors' criterion becomes the law's stuck spring (slipping) by itself;
    // contact_area, which reports the junction phases, says to take it out.
    for (const char* law : {"coulomb", "slip_weakening"})
        swap_into_headline(
            {"friction", fmt::format("friction:\n  type: {}\n", law), {contact_area}, {"contact_area"}, ""});
    // Rate and state (no contact measure: slip_rate) also needs an integrator that takes its velocity
    // dependence implicitly: said by check, not at the end of settling.
    swap_into_headline({"friction",
                        "friction:\n  type: rate_state\n",
                        {contact_area, {"integrator", "type: imex_euler"}},
                        {"contact_area"},
                        " --set 'integrator={type: imex_euler, dt: 2.0e-7}'"});
}

// A stick-slip law's regularised sign is a dashpot that an explicit step cannot resolve, so the
// law's events depend on the step (theory.md §0). check and run say so, once, with the bound and the
// integrator that takes it implicitly (on a line and in a 3D body's interface plane), and run.yaml
// records it; the shipped scenes step with imex_euler (the 3D one in the hybrid's dynamic phases) and
// are not warned.
TEST(FrictionSwap, AStickSlipLawSteppedExplicitlyIsWarnedThatItsEventsDependOnTheStep) {
    const fs::path dir = testing::work_directory();
    const std::string scene = FRICTIONLAB_SOURCE_DIR "/configs/peer_laws/maegawa_coulomb.yaml";
    const auto shipped = testing::frictionlab("check " + scene, dir);
    EXPECT_EQ(shipped.code, 0) << shipped.output;
    EXPECT_EQ(shipped.output.find("warning"), std::string::npos) << shipped.output;

    const std::string rk4 = " --set 'integrator={type: rk4, dt: 2.0e-7}'";
    const std::string said =
        "warning: integrator: rk4 steps coulomb explicitly: its regularised sign, a slipping block's force "
        "-S tanh(v/v_r) with v_r = 1e-06 m/s, is a dashpot of up to S/v_r as its velocity passes through zero, "
        "which a step of 2e-07 s resolves only while the kinetic force S stays below 2.8 m v_r/dt = 0.000448 N "
        "(m = 3.2e-05 kg, the lightest block); beyond, the events depend on the step (theory.md §0); "
        "integrator: {type: imex_euler, dt: 2e-07} takes it implicitly";
    const auto checked = testing::frictionlab("check " + scene + rk4, dir);
    EXPECT_EQ(checked.code, 0) << checked.output;
    const auto at = checked.output.find(said);
    EXPECT_NE(at, std::string::npos) << checked.output;
    EXPECT_EQ(checked.output.find("warning", at + 1), std::string::npos) << "once: " << checked.output;

    const auto ran = testing::frictionlab("run -q " + scene + rk4 + " --set stages[1].duration=1.0e-4 -o out", dir);
    EXPECT_EQ(ran.code, 0) << ran.output;
    EXPECT_NE(ran.output.find(said.substr(std::string("warning: ").size())), std::string::npos) << ran.output;
    const YAML::Node caveats = YAML::LoadFile((dir / "out" / "run.yaml").string())["caveats"];
    ASSERT_TRUE(caveats.IsSequence());
    ASSERT_EQ(caveats.size(), 1u);
    EXPECT_EQ("warning: " + caveats[0].as<std::string>(), said);

    const std::string scene_3d = FRICTIONLAB_SOURCE_DIR "/configs/3d/maegawa_coulomb.yaml";
    const auto shipped_3d = testing::frictionlab("check " + scene_3d, dir);
    EXPECT_EQ(shipped_3d.code, 0) << shipped_3d.output;
    EXPECT_EQ(shipped_3d.output.find("warning"), std::string::npos) << shipped_3d.output;
    const auto in_3d = testing::frictionlab("check " + scene_3d + " --set integrator.dynamic=rk4", dir);
    EXPECT_EQ(in_3d.code, 0) << in_3d.output;
    EXPECT_NE(in_3d.output.find("warning: integrator: quasi_static_hybrid steps coulomb explicitly"), std::string::npos)
        << in_3d.output;
    EXPECT_NE(in_3d.output.find("(theory.md §0); integrator: {type: imex_euler, dt: 2e-07} takes it implicitly"),
              std::string::npos)
        << in_3d.output;
}

TEST(FrictionSwap, TheHeadlineTakesEveryBulkModelByItsBulkBlock) {
    swap_into_headline({"bulk", "bulk:\n  type: spring_lattice_2d\n", {}, {}, ""});
    swap_into_headline({"bulk", "bulk:\n  type: chain_1d\n", {}, {}, ""});
}

}  // namespace
}  // namespace frictionlab
