#include "frictionlab/campaign/runner.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <deque>
#include <map>
#include <thread>

#include <fmt/format.h>
#include <spdlog/sinks/stdout_sinks.h>

#include "frictionlab/campaign/mpi.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/base/interrupt_signals.hpp"
#include "frictionlab/base/live_line.hpp"
#include "frictionlab/base/parallel_chunks.hpp"
#include "frictionlab/output/output_directory.hpp"

namespace frictionlab {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/// How far a run of `c` that ended with `status` got: the run says so in its run.yaml (its exception
/// does not). A run refused before it began leaves an earlier attempt's run.yaml, or none: nowhere.
RunSummary reached(const CampaignRun& c, const std::string& status) {
    try {
        const auto recorded = read_recorded_run(c.scene.output_directory);
        if (recorded && recorded->status == status && recorded->scene_hash == c.scene.hash) return recorded->summary;
    } catch (const InputError&) {  // something else in its place
    }
    return {};
}

/// The child's side: the run and its record, its log in `log_file`; never returns.
[[noreturn]] void run_case_here(const CampaignRun& c, const fs::path& log_file, const Registry& registry,
                                const CampaignOptions& campaign) {
    const int fd = ::open(log_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
        ::dup2(fd, STDOUT_FILENO);
        ::dup2(fd, STDERR_FILENO);
        ::close(fd);
    }
    auto log = std::make_shared<spdlog::logger>("frictionlab", std::make_shared<spdlog::sinks::stderr_sink_st>());
    log->set_pattern("[%H:%M:%S.%e] %l: %v");
    set_worker_threads(campaign.threads > 0 ? campaign.threads
                       : mpi_size() > 1     ? 1
                                            : std::max(1, available_threads() / std::max(1, campaign.jobs)));
    CaseRecord record;
    record.scene_hash = c.scene.hash;
    int code = exit_code::ok;
    try {
        // The directory may hold an interrupted or failed attempt: FrictionLab's own, so replaceable;
        // one of this very scene stopped with a checkpoint goes on from it.
        RunOptions options;
        options.overwrite = true;
        options.allow_unstable_step = campaign.allow_unstable_step;
        // The flag of the handlers the campaign installed, inherited with them: the campaign passes
        // its stop signal on to this process, which then stops like `frictionlab run`.
        options.stop_signal = campaign.stop_signal;
        const auto previous = read_recorded_run(c.scene.output_directory);
        options.resume = previous && previous->resumable() && previous->scene_hash == c.scene.hash;
        if (options.resume) log->info("resuming the interrupted case from its checkpoint");
        record.summary = run_scene(c.scene, registry, *log, options);
        record.status = "done";
    } catch (const Interrupted& e) {
        log->warn("run {}", e.what());
        record.status = "interrupted";
        record.reason = e.what();
        record.summary = reached(c, record.status);
        code = InterruptSignals::exit_status(e.signal);
    } catch (const std::exception& e) {
        log->error("run failed: {}", e.what());
        record.status = "failed";
        record.reason = e.what();
        record.summary = reached(c, record.status);
        code = exit_code::run_failure;
    }
    std::error_code ec;
    try {
        // A run refused before its first step leaves no directory; its case's record goes in one,
        // marked as FrictionLab's so that running the campaign again replaces it.
        if (!fs::is_directory(c.scene.output_directory, ec)) prepare_output_directory(c.scene.output_directory, true);
        write_case_record(c.scene.output_directory, record);
    } catch (const InputError& e) {  // its place taken by something not FrictionLab's
        log->error("{}", e.what());
        code = exit_code::run_failure;
    } catch (const RunError& e) {  // a full disk: without its record, the case counts as not run and reruns
        log->error("{}", e.what());
        code = exit_code::run_failure;
    }
    log->flush();
    std::fflush(nullptr);
    std::_Exit(code);  // no atexit handlers: they belong to the parent (and MPI)
}

pid_t start_case(const CampaignRun& c, const fs::path& logs, const Registry& registry, const CampaignOptions& options) {
    const pid_t parent = ::getpid();
    const pid_t child = ::fork();
    if (child < 0) throw RunError(fmt::format("cannot start case {}: {}", c.name, std::strerror(errno)));
    if (child == 0) {
        // A case dies with its campaign (killed): a re-run then runs it again.
        ::prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (::getppid() != parent) std::_Exit(exit_code::run_failure);
        // A process group of its own: a terminal's Ctrl-C reaches the campaign alone, which passes
        // it on once (a second one would stop the case at once, without its checkpoint).
        ::setpgid(0, 0);
        run_case_here(c, logs / (c.name + ".log"), registry, options);
    }
    return child;
}

bool stopping(const CampaignOptions& options) { return options.stop_signal && options.stop_signal->load() != 0; }

/// Waits for one case's process to end, passing a stop signal received meanwhile on to it.
int wait_for(pid_t child, const CampaignOptions& options) {
    int status = 0;
    bool passed_on = false;
    for (;;) {
        const pid_t ended = ::waitpid(child, &status, options.stop_signal ? WNOHANG : 0);
        if (ended == child || (ended < 0 && errno != EINTR)) return status;
        if (stopping(options) && !passed_on) {
            ::kill(child, options.stop_signal->load());
            passed_on = true;
        } else if (ended == 0) {
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
    }
}

/// The record a finished case left, or one saying how its process ended if it left none (a crash,
/// a kill, or a failure before its directory existed).
CaseRecord outcome(const CampaignRun& c, int status, const fs::path& logs) {
    CaseRecord record = read_case_record(c.scene.output_directory);
    if (record.scene_hash == c.scene.hash && record.status != "not run") return record;
    record = CaseRecord{};
    record.status = "failed";
    record.scene_hash = c.scene.hash;
    const auto log = (logs / (c.name + ".log")).string();
    if (WIFSIGNALED(status))
        record.reason =
            fmt::format("killed by signal {} ({}); see {}", WTERMSIG(status), strsignal(WTERMSIG(status)), log);
    else
        record.reason = fmt::format("exited with status {} before recording its outcome; see {}",
                                    WIFEXITED(status) ? WEXITSTATUS(status) : -1, log);
    return record;
}

/// The campaign's one live line (cases done, running, failed; ETA), or a log line per case.
class Progress {
public:
    Progress(std::size_t total, std::size_t reused, bool live, spdlog::logger& log)
        : total_(total), done_(reused), live_(live), log_(log), start_(Clock::now()) {}

    void started() {
        ++running_;
        show();
    }
    void finished(const CampaignRun& c, const CaseRecord& r) {
        --running_;
        ++done_;
        ++finished_here_;
        if (r.status != "done") ++failed_;
        if (!live_) {
            if (r.status == "done")
                log_.info("case {} done in {:.3g} s ({}/{})", c.name, r.summary.wall_seconds, done_, total_);
            else
                log_.warn("case {} failed: {} ({}/{})", c.name, r.reason, done_, total_);
        } else if (r.status != "done") {
            clear_live_line();
            std::fprintf(stderr, "case %s failed: %s\n", c.name.c_str(), r.reason.c_str());
        }
        show();
    }
    void end() {
        if (live_) std::fprintf(stderr, "\n");
    }

private:
    void show() const {
        if (!live_) return;
        const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
        std::string eta = "ETA --";
        if (finished_here_ > 0 && done_ < total_) {
            // Cases finish at the rate they have so far, whatever ran them.
            const double left = elapsed / static_cast<double>(finished_here_) * static_cast<double>(total_ - done_);
            eta = fmt::format("ETA {:.0f} s", std::ceil(left));
        }
        show_live_line(fmt::format("sweep: {}/{} done, {} running, {} failed, {:.0f} s, {}", done_, total_, running_,
                                   failed_, elapsed, eta));
    }

    std::size_t total_, done_, running_ = 0, failed_ = 0, finished_here_ = 0;
    bool live_;
    spdlog::logger& log_;
    Clock::time_point start_;
};

/// A worker rank: runs the cases rank 0 sends until it sends -1.
void serve(const std::vector<CampaignRun>& runs, const fs::path& logs, const Registry& registry,
           const CampaignOptions& options) {
    mpi_work::Report report;
    for (int next = mpi_work::report_and_receive(report); next >= 0; next = mpi_work::report_and_receive(report)) {
        const auto& c = runs.at(static_cast<std::size_t>(next));
        report = {next, wait_for(start_case(c, logs, registry, options), options)};
    }
}

}  // namespace

void prepare_campaign_directory(const Campaign& campaign, const fs::path& output, const CampaignOptions& options) {
    const bool goes_on =
        options.reuse_finished && !options.overwrite && fs::exists(output) && created_by_frictionlab(output);
    if (!goes_on) prepare_output_directory(output, options.overwrite, {campaign.scene, campaign.file});
}

std::vector<CaseRecord> run_campaign(const std::vector<CampaignRun>& runs, const fs::path& output,
                                     const Registry& registry, spdlog::logger& log, const CampaignOptions& options) {
    const fs::path logs = output / "logs";
    if (mpi_rank() != 0) {
        serve(runs, logs, registry, options);
        return {};
    }
    fs::create_directories(output / "cases");
    fs::create_directories(logs);
    std::vector<CaseRecord> records(runs.size());
    std::deque<std::size_t> queue;
    for (std::size_t i = 0; i < runs.size(); ++i) {
        CaseRecord earlier = read_case_record(runs[i].scene.output_directory);
        if (options.reuse_finished && earlier.status == "done" && earlier.scene_hash == runs[i].scene.hash) {
            earlier.reused = true;
            records[i] = earlier;
        } else {
            queue.push_back(i);
        }
    }
    const std::size_t reused = runs.size() - queue.size();
    if (reused > 0) log.info("{} of {} cases finished earlier with the same scene: not run again", reused, runs.size());
    Progress progress(runs.size(), reused, options.live_progress, log);

    std::map<pid_t, std::size_t> running;  // local child processes
    int busy_workers = 0, idle_workers = mpi_size() - 1;
    std::vector<int> waiting_workers;
    const auto finish = [&](std::size_t i, int status) {
        records[i] = outcome(runs[i], status, logs);
        progress.finished(runs[i], records[i]);
    };
    const std::size_t jobs = static_cast<std::size_t>(std::max(1, options.jobs));
    bool passed_on = false;
    while (!queue.empty() || !running.empty() || busy_workers > 0 || idle_workers > 0) {
        if (stopping(options) && !passed_on) {
            // No case starts any more; each running one stops with a checkpoint, to go on from when
            // the campaign runs again. Workers stop theirs (the launcher signals every rank).
            queue.clear();
            for (const auto& [child, i] : running) ::kill(child, options.stop_signal->load());
            passed_on = true;
        }
        // Idle workers first report (case -1) and then wait; hand them work or send them home.
        int worker = 0;
        mpi_work::Report report;
        while (mpi_work::poll_report(worker, report)) {
            if (report.case_index >= 0) {
                --busy_workers;
                finish(static_cast<std::size_t>(report.case_index), report.exit_status);
            } else {
                --idle_workers;
            }
            if (!queue.empty()) {
                mpi_work::send_case(worker, static_cast<int>(queue.front()));
                queue.pop_front();
                ++busy_workers;
                progress.started();
            } else {
                mpi_work::send_case(worker, -1);
            }
        }
        while (running.size() < jobs && !queue.empty()) {
            const std::size_t i = queue.front();
            queue.pop_front();
            running.emplace(start_case(runs[i], logs, registry, options), i);
            progress.started();
        }
        if (mpi_size() == 1 && !options.stop_signal) {
            // Only local children: sleep in waitpid until one ends.
            if (running.empty()) continue;
            int status = 0;
            const pid_t child = ::waitpid(-1, &status, 0);
            if (child < 0) continue;  // EINTR
            if (const auto it = running.find(child); it != running.end()) {
                finish(it->second, status);
                running.erase(it);
            }
            continue;
        }
        // Local children and remote ranks, or a stop signal: poll them.
        int status = 0;
        const pid_t child = running.empty() ? 0 : ::waitpid(-1, &status, WNOHANG);
        if (child > 0) {
            if (const auto it = running.find(child); it != running.end()) {
                finish(it->second, status);
                running.erase(it);
            }
        } else {
            std::this_thread::sleep_for(std::chrono::milliseconds(mpi_size() > 1 ? 2 : 20));
        }
    }
    progress.end();
    return records;
}

}  // namespace frictionlab
