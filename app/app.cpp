// The wardray command: the options, then one scene loaded, built, rendered and written; --check's report.
#include "app/app.h"

#include <unistd.h>

#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "app/cache_carry.h"
#include "app/diff_command.h"
#include "app/options.h"
#include "app/process_group.h"
#include "app/process_limits.h"
#include "app/run.h"
#include "app/stats.h"
#include "core/diagnostics.h"
#include "geometry/coincident_surfaces.h"
#include "geometry/scene_geometry.h"
#include "texture/pattern_wraps.h"

namespace wardray::app {

namespace {


std::string vec_text(const Vec3& v) {
    std::ostringstream s;
    s << '<' << v.x << ", " << v.y << ", " << v.z << '>';
    return s.str();
}

// Whether any layer or texture_map entry of the texture, at any depth, has a grainy finish (`crand`).
bool texture_has_crand(const scene::Texture& t) {
    if (t.finish.crand > 0.0) return true;
    for (const scene::Texture& layer : t.layers)
        if (texture_has_crand(layer)) return true;
    for (const scene::TextureMapEntry& e : t.texture_map)
        if (texture_has_crand(e.texture)) return true;
    return false;
}

bool object_has_crand(const scene::Object& o) {
    if (texture_has_crand(o.texture)) return true;
    for (const scene::Texture& t : o.interior_texture)
        if (texture_has_crand(t)) return true;
    if (const auto* csg = std::get_if<scene::Csg>(&o.shape))
        for (const scene::Object& child : csg->children)
            if (object_has_crand(child)) return true;
    return false;
}

// The sources of randomness the scene uses, as --check names them: what makes two renders at the scene's own
// settings differ by noise (the census renders such scenes converged). Found in the scene as parsed, so also in
// textures and lights that come from include files.
std::vector<std::string> randomness(const scene::Scene& scene) {
    std::vector<std::string> found;
    if (scene.global.radiosity) found.emplace_back("radiosity");
    for (const scene::Light& l : scene.lights) {
        if (l.area && l.jitter) {
            found.emplace_back("area light jitter");
            break;
        }
    }
    for (const scene::Object& o : scene.objects) {
        if (object_has_crand(o)) {
            found.emplace_back("crand");
            break;
        }
    }
    if (scene.camera.aperture > 0.0 && scene.camera.blur_samples > 1) found.emplace_back("focal blur");
    return found;
}

// --check: what the scene holds, in a form a person can read.
void describe_scene(const scene::Scene& scene, std::ostream& out) {
    out << "scene: " << scene.path << "\n";
    out << "version: " << scene.version << "\n";
    out << "camera: "
        << scene::camera_type_name(scene.camera.type)
        << " at " << vec_text(scene.camera.location) << " looking along " << vec_text(scene.camera.direction)
        << "\n";
    // "objects: 3 (box 1, sphere 2)": a total, then the count of each kind in name order.
    auto counts = [&out](const char* label, std::size_t total, const std::map<std::string, int>& by_kind) {
        out << label << ": " << total;
        const char* separator = " (";
        for (const auto& [name, n] : by_kind) {
            out << separator << name << ' ' << n;
            separator = ", ";
        }
        out << (by_kind.empty() ? "" : ")") << "\n";
    };
    std::map<std::string, int> objects;
    for (const scene::Object& o : scene.objects) ++objects[scene::shape_keyword(o.shape)];
    counts("objects", scene.objects.size(), objects);
    std::map<std::string, int> lights;
    for (const scene::Light& l : scene.lights) ++lights[std::string(scene::light_type_name(l.type))];
    counts("lights", scene.lights.size(), lights);
    out << "radiosity: " << (scene.global.radiosity ? "on" : "off") << "\n";
    const std::vector<std::string> random = randomness(scene);
    out << "randomness:";
    for (std::size_t i = 0; i < random.size(); ++i) out << (i ? ", " : " ") << random[i];
    out << (random.empty() ? " none\n" : "\n");
    out << "warnings: " << scene.warnings.size() << "\n";
    for (const Diagnostic& w : scene.warnings) out << "  " << w.loc.path << ':' << w.loc.line << ':'
                                                            << w.loc.column << ": " << w.message << "\n";
}

// Objects the geometry could not place are left out, each with a warning at its statement that says why and, when
// the refused part is written elsewhere (a deep level, a degenerate child), where that part is.
void warn_skipped_objects(const scene::Scene& scene, const geometry::SceneGeometry& geometry) {
    const std::vector<std::uint32_t>& skipped = geometry.skipped_objects();
    const std::vector<geometry::SkipReason>& reasons = geometry.skip_reasons();
    for (std::size_t k = 0; k < skipped.size(); ++k) {
        const scene::Object& object = scene.objects[skipped[k]];
        const geometry::SkipReason& why = reasons[k];
        Diagnostic d;
        d.severity = Severity::Warning;
        d.loc = object.loc;
        const bool elsewhere = !why.where.path.empty() && why.where != object.loc;
        const std::string part = why.where.path + ':' + std::to_string(why.where.line) + ':' +
                                 std::to_string(why.where.column);
        d.message = std::string(scene::shape_keyword(object.shape));
        if (why.too_deep) {
            const int limit = geometry::max_csg_depth();
            d.message += " nests CSG more than " + std::to_string(limit) + " levels deep";
            if (elsewhere) d.message += " (level " + std::to_string(limit + 1) + " is at " + part + ")";
            d.message += " and is not rendered; build it as fewer levels (a flat union) or as a mesh";
        } else {
            d.message += " is degenerate (zero size, singular transform or non-finite numbers";
            if (elsewhere) d.message += ": the part at " + part;
            d.message += ") and is not rendered";
        }
        std::cerr << format_diagnostic(d);
    }
}

// One frame of the job from its file to its image: each step prints why it fails; returns the exit status. Shared
// among processes, every rank loads and builds the scene, they render it together, and rank 0 writes it; after the
// `last` frame's render the processes leave their group while rank 0 writes.
int render_one_frame(const Job& job, const Frame& frame, Clock::time_point start, ProcessGroup& group,
                     CacheCarry& carry, bool last) {
    const std::optional<LoadedScene> loaded = load_scene(job.options, frame.clock);
    if (!group.agree(loaded.has_value(), "parse the scene")) return kExitScene;
    const scene::Scene& scene = loaded->scene;
    // Surfaces on one another, which POV-Ray draws as a random speckle: said before anything is rendered.
    if (group.root()) {
        for (const Diagnostic& w : geometry::coincident_surface_warnings(scene)) std::cerr << format_diagnostic(w);
        // Likewise a texture that jumps exactly on a surface (a pattern wrapping there).
        for (const Diagnostic& w : texture::pattern_wrap_warnings(scene)) std::cerr << format_diagnostic(w);
    }
    if (job.options.check_only) {
        if (group.root()) describe_scene(scene, std::cout);
        return kExitOk;
    }
    const std::optional<BuiltGeometry> built = build_geometry(scene);
    if (!group.agree(built.has_value(), "build the scene's geometry")) return kExitScene;
    warn_skipped_objects(scene, *built->geometry);
    Illumination illumination = build_illumination(scene, *built->geometry, job.options);
    if (illumination.cache && job.options.radiosity_load) group.share_cache(*illumination.cache);
    // --gi-carry: the previous frame's records (every rank holds the same ones after a shared render).
    if (illumination.cache) {
        const auto counts = carry.start(scene, *illumination.cache);
        if (counts && job.options.verbose && group.root())
            std::cerr << "wardray: " << frame.output.string() << ": carried " << counts->first
                      << " irradiance records, dropped " << counts->second << "\n";
    }
    const RenderedFrame rendered =
        render_frame(scene, illumination, job.options, job.region, group.communicator());
    for (const Diagnostic& w : built->geometry->shape_warnings()) std::cerr << format_diagnostic(w);
    if (illumination.cache) carry.finish(scene, *illumination.cache);
    if (last) group.release();
    const auto write_start = Clock::now();
    Job frame_job = job;
    frame_job.output = frame.output;
    // Only rank 0 writes; the others wait to hear that it did.
    bool written = !group.root() || write_outputs(frame_job, scene, illumination, rendered.result);
    const PhaseTimes times{loaded->seconds, built->seconds, rendered.seconds, seconds_since(write_start)};
    if (written && group.root() && job.options.stats)
        written = write_stats(*job.options.stats, frame_job, scene, illumination, rendered.result, times,
                              PeakMemory{loaded->peak_bytes, built->peak_bytes, peak_resident_bytes()}, start);
    if (!group.agree(written, "write the output")) return kExitScene;
    if (job.options.verbose && group.root())
        std::cerr << "wardray: wrote " << frame.output.string() << " (" << job.options.width << "x"
                  << job.options.height << ") in " << seconds_since(start) << " s\n";
    return kExitOk;
}

// Frames of an animation split among the ranks: each renders whole frames on its own (the image is the one a plain
// run makes), round by round, and sends them to rank 0, which alone writes. `frames` are those left to render.
int run_frames_split(const Job& job, const std::vector<const Frame*>& frames, ProcessGroup& group) {
    const auto ranks = static_cast<std::size_t>(group.size());
    const auto rank = static_cast<std::size_t>(group.rank());
    for (std::size_t round = 0; round < frames.size(); round += ranks) {
        bool ok = true;
        std::string image;
        if (round + rank < frames.size()) {
            Frame frame = *frames[round + rank];
            // Another rank writes its frame to a local temporary file and hands the bytes to rank 0.
            const std::filesystem::path local =
                group.root() ? frame.output
                             : std::filesystem::temp_directory_path() /
                                   ("wardray-" + std::to_string(::getpid()) + "-" + frame.output.filename().string());
            frame.output = local;
            ProcessGroup alone{ProcessGroup::Alone{}};
            CacheCarry none(CarryMode::Off);
            ok = render_one_frame(job, frame, Clock::now(), alone, none, false) == kExitOk;
            if (ok && !group.root()) {
                std::ifstream in(local, std::ios::binary);
                image.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
                ok = static_cast<bool>(in) || in.eof();
                std::error_code ec;
                std::filesystem::remove(local, ec);
            }
        }
        if (!group.agree(ok, "render its frame")) return kExitScene;
        const std::vector<render::Bytes> all = group.gather(render::Bytes(image.begin(), image.end()));
        bool written = true;
        for (std::size_t r = 1; group.root() && r < all.size() && round + r < frames.size(); ++r) {
            const Frame& frame = *frames[round + r];
            const auto error = render::write_atomically(frame.output, [&](const std::filesystem::path& tmp)
                                                                           -> std::optional<std::string> {
                std::ofstream out(tmp, std::ios::binary);
                out.write(reinterpret_cast<const char*>(all[r].data()), static_cast<std::streamsize>(all[r].size()));
                out.close();
                if (!out) return std::string("write failed");
                return std::nullopt;
            });
            if (error) std::cerr << "wardray: error: " << *error << "\n";
            written = written && !error;
            if (!error && job.options.verbose)
                std::cerr << "wardray: wrote " << frame.output.string() << " (rendered by rank " << r << ")\n";
        }
        if (!group.agree(written, "write the output")) return kExitScene;
    }
    return kExitOk;
}

// True when the frames may go to the ranks whole: several frames rendered afresh, with no per-frame file beside
// the image (the radiosity file, statistics, --aov) that only a render shared frame by frame writes.
bool frames_split(const Job& job, const ProcessGroup& group) {
    const Options& o = job.options;
    return group.shared() && job.frames.size() > 1 && !o.check_only && o.gi_carry == CarryMode::Off &&
           !o.radiosity_load && !o.radiosity_save && !o.stats && !o.aov_irradiance && !o.aov_records;
}

// One scene, each frame of it parsed afresh (POV-Ray compat); +C skips the frames whose image already exists.
int run_frames(const Job& job, Clock::time_point start, ProcessGroup& group) {
    CacheCarry carry(job.options.gi_carry);
    const bool split = frames_split(job, group);
    std::vector<const Frame*> left;
    for (const Frame& frame : job.frames) {
        std::error_code ec;
        // Rank 0 writes the images, so its folder decides what +C keeps.
        const bool kept = job.options.continue_trace && !job.options.check_only &&
                          group.root_decides(group.root() && std::filesystem::exists(frame.output, ec));
        if (kept) {
            if (job.options.verbose && group.root())
                std::cerr << "wardray: " << frame.output.string() << " exists; kept (+C)\n";
            continue;
        }
        if (split) {
            left.push_back(&frame);
            continue;
        }
        const Clock::time_point frame_start = &frame == &job.frames.front() ? start : Clock::now();
        const bool last = &frame == &job.frames.back();
        if (const int status = render_one_frame(job, frame, frame_start, group, carry, last); status != kExitOk)
            return status;
        if (job.options.check_only) break;
    }
    return split ? run_frames_split(job, left, group) : kExitOk;
}

int run_scene(Options options, const std::string& argv0, Clock::time_point start) {
    const std::optional<Job> job = resolve_job(std::move(options), argv0);
    if (!job) return kExitScene;
    if (const std::optional<int> refused = refuse_job(*job)) return *refused;
    const auto thread_limit = prepare_process(job->options);
    // Under mpirun, the ranks started together; a rank that fails unexpectedly ends them all, never leaving the
    // others waiting in an exchange.
    ProcessGroup group;
    if (!group.shared()) return run_frames(*job, start, group);
    try {
        return run_frames(*job, start, group);
    } catch (const std::bad_alloc&) {
        group.fail("out of memory");
    } catch (const std::exception& e) {
        group.fail(e.what());
    }
}

}  // namespace

int run(const std::vector<std::string>& args, const std::string& argv0) {
    const auto start = Clock::now();
    if (!args.empty() && args[0] == "diff")
        return run_diff_command(std::vector<std::string>(args.begin() + 1, args.end()));
    auto parsed = parse_command_line(args);
    if (auto* error = std::get_if<UsageError>(&parsed)) {
        if (error->in_file) {  // a mistake in an INI file: its file:line, and no usage text
            std::cerr << error->message << "\n";
            return kExitScene;
        }
        std::cerr << "wardray: " << error->message << "\n" << usage_text();
        return kExitUsage;
    }
    Options options = std::get<Options>(parsed);
    for (const std::string& warning : options.warnings) std::cerr << warning << "\n";
    if (options.show_help) {
        std::cout << usage_text();
        return kExitOk;
    }
    if (options.show_version) {
        std::cout << "wardray " << WARDRAY_VERSION << "\n";
        return kExitOk;
    }
    return run_scene(std::move(options), argv0, start);
}

}  // namespace wardray::app
