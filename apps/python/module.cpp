// frictionlab._core: the C++ side of the Python module (the package's __init__.py wraps it). It
// reads and validates scenes exactly as the command line does, runs them in-process, answers what
// `frictionlab list` and `frictionlab doc` print, and gives frictionlab.ensembles the bootstrap
// intervals the campaign tables use.
#include <dlfcn.h>

#include <atomic>
#include <csignal>
#include <chrono>
#include <cstdlib>
#include <exception>
#include <future>
#include <memory>
#include <optional>
#include <thread>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "../frictionlab/doc_writer.hpp"
#include "../frictionlab/type_selector.hpp"
#include "frictionlab/base/parallel_chunks.hpp"
#include "frictionlab/base/errors.hpp"
#include "frictionlab/plugins/search.hpp"
#include "frictionlab/plugins/registry.hpp"
#include "frictionlab/simulation/run.hpp"
#include "frictionlab/scene/scene.hpp"
#include "frictionlab/base/version.hpp"
#include "frictionlab/campaign/ensemble_statistics.hpp"

namespace py = pybind11;
namespace fl = frictionlab;
namespace fs = std::filesystem;

namespace {

/// A scene that failed validation: every diagnostic, raised in Python as frictionlab.SceneError.
struct SceneInvalid : std::exception {
    std::string name;
    fl::Diagnostics diagnostics;
    std::string text;
    SceneInvalid(std::string n, fl::Diagnostics d) : name(std::move(n)), diagnostics(std::move(d)) {
        text = diagnostics.format() + std::to_string(diagnostics.list().size()) +
               (diagnostics.list().size() == 1 ? " error" : " errors") + " in " + name;
    }
    const char* what() const noexcept override { return text.c_str(); }
};

/// The plugins shipped with the module: the build tree and the install tree place the module and
/// the plugins differently, so both relative paths (from CMake) are tried from the module's folder.
std::optional<fs::path> shipped_plugins() {
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&shipped_plugins), &info) == 0 || !info.dli_fname) return std::nullopt;
    const fs::path here = fs::path(info.dli_fname).parent_path();
    for (const char* relative : {FRICTIONLAB_PYTHON_BUILD_PLUGINS, FRICTIONLAB_PYTHON_INSTALL_PLUGINS}) {
        std::error_code ec;
        const fs::path dir = fs::weakly_canonical(here / relative, ec);
        if (!ec && fs::is_directory(dir)) return dir;
    }
    return std::nullopt;
}

std::vector<fs::path> plugin_directories(const std::vector<fs::path>& explicit_paths,
                                         const std::vector<fs::path>& scene) {
    const char* env = std::getenv("FRICTIONLAB_PLUGIN_PATH");
    return fl::plugin_directories(explicit_paths, scene, env ? env : "", shipped_plugins());
}

std::shared_ptr<spdlog::logger> make_logger(const std::string& level) {
    auto log = std::make_shared<spdlog::logger>("frictionlab", std::make_shared<spdlog::sinks::stderr_color_sink_mt>());
    log->set_level(spdlog::level::from_str(level));
    log->set_pattern("[%H:%M:%S.%e] %^%l%$: %v");
    return log;
}

/// A validated scene with the plugins its types come from. It keeps its source and overrides, so
/// that an output directory given to run() is one more override, as `-o` is on the command line
/// (the scene hash then matches the command line's run).
class PyScene {
public:
    static PyScene load(const fs::path& file, const std::vector<std::string>& overrides,
                        const std::vector<fs::path>& plugin_paths) {
        return PyScene(file, std::nullopt, overrides, plugin_paths);
    }
    static PyScene from_yaml(const std::string& text, const std::string& name,
                             const std::vector<std::string>& overrides, const std::vector<fs::path>& plugin_paths) {
        return PyScene(name, text, overrides, plugin_paths);
    }

    const fl::Scene& scene() const { return scene_; }

    /// Runs in this process, the GIL released; Ctrl-C stops the run (its outputs closed) and raises
    /// KeyboardInterrupt.
    py::dict run(const std::optional<fs::path>& output, bool progress, bool overwrite, bool allow_unstable_step,
                 bool resume, const std::string& log_level, int threads) const {
        const PyScene* target = this;
        std::optional<PyScene> redirected;
        if (output) {
            auto overrides = overrides_;
            overrides.push_back("output=" + output->string());
            redirected.emplace(PyScene(source_, text_, overrides, plugin_paths_));
            target = &*redirected;
        }
        fl::RunOptions options;
        // Provenance as the command records it: how this process was started, and the --set list.
        options.command_line = py::module_::import("sys").attr("argv").cast<std::vector<std::string>>();
        options.overrides = overrides_;
        options.overwrite = overwrite;
        options.allow_unstable_step = allow_unstable_step;
        options.resume = resume;
        options.live_progress = progress;
        fl::set_worker_threads(threads > 0 ? threads : fl::available_threads());  // as `frictionlab run`
        std::atomic<int> stop{0};  // as the command's signal handlers set it: the run ends `interrupted`
        options.stop_signal = &stop;
        auto log = make_logger(log_level);

        // The run steps in a worker thread; this (main) thread waits with the GIL released and looks
        // for signals, which CPython delivers to the main thread only, ten times a second.
        auto result = std::async(std::launch::async,
                                 [&] { return fl::run_scene(target->scene_, *target->registry_, *log, options); });
        bool interrupted = false;
        std::optional<py::error_already_set> signal_error;
        {
            py::gil_scoped_release release;
            while (result.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready) {
                if (interrupted) continue;
                py::gil_scoped_acquire acquire;
                if (PyErr_CheckSignals() != 0) {
                    signal_error.emplace();  // takes the pending KeyboardInterrupt
                    interrupted = true;
                    stop = SIGINT;
                }
            }
        }
        if (signal_error) {
            try {
                result.get();
            } catch (const std::exception&) {
                // the run stopped as asked (Interrupted): run.yaml records it
            }
            throw *signal_error;
        }
        const fl::RunSummary s = result.get();
        py::dict d;
        d["output"] = target->scene_.output_directory;
        d["steps"] = s.steps;
        d["evaluations"] = s.evaluations;
        d["simulated_time"] = s.simulated_time;
        d["wall_seconds"] = s.wall_seconds;
        d["cpu_seconds"] = s.cpu_seconds;
        return d;
    }

private:
    PyScene(fs::path source, std::optional<std::string> text, std::vector<std::string> overrides,
            std::vector<fs::path> plugin_paths)
        : source_(std::move(source)),
          text_(std::move(text)),
          overrides_(std::move(overrides)),
          plugin_paths_(std::move(plugin_paths)),
          registry_(std::make_shared<fl::Registry>()) {
        fl::Diagnostics diagnostics;
        auto document = text_ ? fl::SceneDocument::parse(*text_, source_.string(), overrides_, diagnostics)
                              : fl::SceneDocument::load(source_, overrides_, diagnostics);
        const auto scene_paths = document.plugin_paths(diagnostics);
        fl::load_plugins(*registry_, plugin_directories(plugin_paths_, scene_paths), *make_logger("warn"));
        scene_ = document.validate(*registry_, diagnostics);
        if (!diagnostics.empty()) throw SceneInvalid(source_.string(), diagnostics);
    }

    fs::path source_;
    std::optional<std::string> text_;
    std::vector<std::string> overrides_;
    std::vector<fs::path> plugin_paths_;
    std::shared_ptr<fl::Registry> registry_;  // the scene's types live in its plugins
    fl::Scene scene_;
};

std::unique_ptr<fl::Registry> shipped_registry(const std::vector<fs::path>& plugin_paths) {
    auto registry = std::make_unique<fl::Registry>();
    fl::load_plugins(*registry, plugin_directories(plugin_paths, {}), *make_logger("warn"));
    return registry;
}

py::list types(const std::vector<fs::path>& plugin_paths) {
    const auto registry = shipped_registry(plugin_paths);
    py::list out;
    for (const auto* t : fl::cli::all_types(*registry)) {
        py::dict d;
        d["kind"] = std::string(fl::to_string(t->kind));
        d["type"] = t->type;
        d["library"] = t->library.empty() ? std::string("built in") : t->library;
        d["summary"] = fl::cli::one_line(*t);
        out.append(d);
    }
    return out;
}

/// `frictionlab doc KIND[/TYPE] --format json` as text (the package parses it).
std::string doc_json(const std::string& kind, const std::string& type, const std::vector<fs::path>& plugin_paths) {
    const auto registry = shipped_registry(plugin_paths);
    const auto types = fl::cli::select_types(*registry, type.empty() ? kind : kind + "/" + type);
    return fl::cli::render_doc(types, fl::cli::DocFormat::json);
}

/// A bootstrap estimate as frictionlab.ensembles reads it: (estimate, low, high, se, interval).
py::tuple estimate_tuple(const fl::BootstrapEstimate& e) {
    return py::make_tuple(e.estimate, e.ci_low, e.ci_high, e.standard_error, e.interval);
}

}  // namespace

PYBIND11_MODULE(_core, m) {
    m.doc() = "FrictionLab's C++ core; use the frictionlab package, which wraps it.";

    static py::exception<fl::InputError> input_error(m, "InputError", PyExc_ValueError);
    static py::exception<fl::RunError> run_error(m, "RunError", PyExc_RuntimeError);
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const SceneInvalid& e) {
            py::list diagnostics;
            for (const auto& d : e.diagnostics.list())
                diagnostics.append(py::make_tuple(d.where.file, d.where.line, d.where.column, d.key_path, d.message));
            py::object error = py::module_::import("frictionlab._errors").attr("SceneError")(e.text, diagnostics);
            PyErr_SetObject(error.get_type().ptr(), error.ptr());
        } catch (const fl::InputError& e) {
            input_error(e.what());
        } catch (const fl::RunError& e) {
            run_error(e.what());
        }
    });

    py::class_<PyScene>(m, "_Scene")
        .def_static("load", &PyScene::load, py::arg("path"), py::arg("set"), py::arg("plugin_paths"))
        .def_static("from_yaml", &PyScene::from_yaml, py::arg("text"), py::arg("name"), py::arg("set"),
                    py::arg("plugin_paths"))
        .def_property_readonly("file", [](const PyScene& s) { return s.scene().file; })
        .def_property_readonly("hash", [](const PyScene& s) { return s.scene().hash; })
        .def_property_readonly("title", [](const PyScene& s) { return s.scene().title; })
        .def_property_readonly("seed", [](const PyScene& s) { return s.scene().seed; })
        .def_property_readonly("output", [](const PyScene& s) { return s.scene().output_directory; })
        .def_property_readonly("resolved_yaml", [](const PyScene& s) { return s.scene().resolved_yaml; })
        .def("run", &PyScene::run, py::arg("output"), py::arg("progress"), py::arg("overwrite"),
             py::arg("allow_unstable_step"), py::arg("resume"), py::arg("log_level"), py::arg("threads"));

    m.def("types", &types, py::arg("plugin_paths"));
    m.def("doc_json", &doc_json, py::arg("kind"), py::arg("type"), py::arg("plugin_paths"));
    m.def("version", &fl::framework_version);
    // The campaign tables' intervals (ensemble_statistics.hpp), for frictionlab.ensembles.
    m.attr("bootstrap_resamples") = fl::bootstrap_resamples;
    m.attr("interval_minimum_values") = fl::interval_minimum_values;
    m.def(
        "bootstrap_mean",
        [](const std::vector<double>& a, std::uint64_t seed, int resamples) {
            return estimate_tuple(fl::bootstrap_mean(a, seed, resamples));
        },
        py::arg("a"), py::arg("seed"), py::arg("resamples"));
    m.def(
        "bootstrap_difference",
        [](const std::vector<double>& a, const std::vector<double>& b, std::uint64_t seed, int resamples) {
            return estimate_tuple(fl::bootstrap_difference(a, b, seed, resamples));
        },
        py::arg("a"), py::arg("b"), py::arg("seed"), py::arg("resamples"));
    m.def(
        "bootstrap_slope",
        [](const std::vector<double>& x, const std::vector<double>& y, std::uint64_t seed, int resamples) {
            return estimate_tuple(fl::bootstrap_slope(x, y, seed, resamples));
        },
        py::arg("x"), py::arg("y"), py::arg("seed"), py::arg("resamples"));
}
