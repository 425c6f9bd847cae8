#include "app/explore_session.hpp"

#include "app/lab_paths.hpp"
#include "app/pick_json.hpp"
#include "app/ray_tree_svg.hpp"
#include "core/build_info.hpp"
#include "core/exercise.hpp"
#include "core/text.hpp"
#include "io/input_file.hpp"
#include "render/integrators.hpp"

#include <filesystem>

namespace rt {

namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

// Samples per pixel the view refines to when neither --spp nor the scene says: enough to
// see antialiasing, soft shadows and lenses settle, few enough to finish in seconds.
constexpr int kExploreSamples = 16;
// A pass slower than this is first shown at a lower resolution after each change.
constexpr double kQuickPassMs = 25;
// After a change's first frame, refining starts once the view has been still this long. While
// the mouse moves (a change every 16 ms or so, two or three of them in this time), a full-size
// pass begun between two changes is thrown away at the second: the cores are better left to
// the next change's pass and to the browser drawing it.
constexpr auto kSettle = std::chrono::milliseconds(40);

json vec_json(const Vec3& v) {
    return json::array({v.x, v.y, v.z});
}

// The camera as a scene file writes it (the keys load_camera_text reads back).
json camera_json(const Camera& c) {
    json j{{"eye", vec_json(c.eye)}, {"target", vec_json(c.target)}, {"up", vec_json(c.up)}};
    if (c.projection == Projection::orthographic) {
        j["projection"] = kProjectionNames[c.projection];
        j["window_height"] = c.window_height;
    } else {
        j["fov"] = c.vertical_fov_degrees;
    }
    if (c.focal_distance != 1) j["focal_distance"] = c.focal_distance;
    if (c.aperture > 0) {
        j["aperture"] = c.aperture;
        if (c.focus_distance > 0) j["focus_distance"] = c.focus_distance;
        j["lens"] = kLensNames[c.lens];
    }
    if (c.shutter_open != 0 || c.shutter_close != 1) j["shutter"] = json::array({c.shutter_open, c.shutter_close});
    return j;
}

template <class Names>
json names_json(const Names& names) {
    return names.all();
}

}  // namespace

ExploreSession::ExploreSession(const ChapterApp& app, const ChapterApp::Invocation& inv) : app_(app) {
    std::vector<std::string> folders = app.scene_folders();
    folders.push_back(shared_assets_dir());
    folders.insert(folders.end(), inv.allow.begin(), inv.allow.end());
    page_files_ = FileAccess(folders, "--allow DIR on the explorer's command line adds a folder");
    invocation_ = render_invocation_ = inv;
    SceneSummary summary;
    Scene scene = inv.scene.build(summary);
    scene.name = inv.scene.name;
    scene_name_ = inv.scene.name;
    scene_file_ = inv.scene.file;
    if (!scene_file_.empty()) {
        scene_text_ = read_input_file(scene_file_, "scene file", limits::scene_file_bytes);
        base_dir_ = std::filesystem::path(scene_file_).parent_path().string();
    }
    if (base_dir_.empty()) base_dir_ = ".";
    scene_antialiasing_ = scene.antialiasing;
    scene_samples_ = scene.samples;
    scene_depth_ = scene.max_depth;
    scene_accel_ = scene.accel_kind;
    (void)options_for(scene, inv);  // refuses what the scene cannot take (a pattern's spp)
    camera_ = scene.camera;
    pending_.scene = std::make_shared<Scene>(std::move(scene));
    pending_.options = true;
    pending_.invocation = inv;
    dirty_ = true;
    finisher_ = std::thread([this] { finish_loop(); });
    thread_ = std::thread([this] { loop(); });
}

ExploreSession::~ExploreSession() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
        overtaken_ = true;
    }
    changed_.notify_all();
    thread_.join();
    {
        std::lock_guard lock(pass_mutex_);
        finish_stop_ = true;
    }
    passed_.notify_all();
    finisher_.join();
}

RenderOptions ExploreSession::options_for(const Scene& scene, const ChapterApp::Invocation& inv) const {
    RenderOptions o = inv.options;
    o.progress = false;
    o.antialiasing = scene.antialiasing;
    if (!inv.pattern.empty()) o.antialiasing.pattern = *kPatternNames.find(inv.pattern);
    if (!inv.filter.empty()) o.antialiasing.filter = *kFilterNames.find(inv.filter);
    if (!inv.spp_given) o.spp = scene.samples > 0 ? scene.samples : kExploreSamples;
    check_budget(o);
    return o;
}

json ExploreSession::state() const {
    std::lock_guard lock(mutex_);
    const ChapterApp::Invocation& inv = invocation_;
    Scene facts;  // the scene's own antialiasing and samples, for the options in effect
    facts.antialiasing = scene_antialiasing_;
    facts.samples = scene_samples_;
    RenderOptions o;
    try {
        o = options_for(facts, inv);
    } catch (const std::invalid_argument&) {
        o = inv.options;
    }
    json scenes = json::array();
    for (const SceneEntry& s : app_.scenes()) scenes.push_back({{"name", s.name}, {"file", s.file}});
    return {{"chapter", app_.id()},
            {"title", app_.title()},
            {"scene", scene_name_},
            {"file", scene_file_},
            {"text", scene_text_.empty() ? json(nullptr) : json(scene_text_)},
            {"scenes", scenes},
            {"camera", camera_json(camera_)},
            {"render_error", render_error_},
            {"options",
             {{"width", o.width},
              {"height", o.height},
              {"spp", o.spp},
              {"seed", o.seed},
              {"threads", o.threads},
              {"depth", inv.max_depth.value_or(scene_depth_)},
              {"accel", inv.accel.empty() ? kAccelNames[scene_accel_] : inv.accel},
              {"pattern", kPatternNames[o.antialiasing.pattern]},
              {"filter", kFilterNames[o.antialiasing.filter]}}},
            {"build",
             {{"version", build_info::version},
              {"track", build_info::track},
              {"from_solutions", build_info::from_solutions},
              {"real", real_name()},
              {"your_exercises", exercise_use::list()}}},
            {"choices",
             {{"shading", names_json(kShadingNames)},
              {"accel", names_json(kAccelNames)},
              {"pattern", names_json(kPatternNames)},
              {"filter", names_json(kFilterNames)},
              {"offset", names_json(kOffsetMethodNames)},
              {"lens", names_json(kLensNames)}}}};
}

std::string ExploreSession::set_scene_text(const std::string& text) {
    const std::string filename = scene_file_.empty() ? "edited.json" : scene_file_;
    ChapterApp::Invocation inv;
    {
        std::lock_guard lock(mutex_);
        inv = invocation_;
    }
    auto scene = std::make_shared<Scene>();
    try {
        *scene = load_scene_text(text, filename, base_dir_, nullptr, page_files_);
        scene->name = scene_name_;
        (void)options_for(*scene, inv);
    } catch (const std::exception& e) {  // SceneError, or a limit (std::invalid_argument)
        return one_line(e.what());
    }
    std::lock_guard lock(mutex_);
    scene_text_ = text;
    scene_antialiasing_ = scene->antialiasing;
    scene_samples_ = scene->samples;
    scene_depth_ = scene->max_depth;
    scene_accel_ = scene->accel_kind;
    camera_ = scene->camera;
    pending_.camera.reset();
    pending_.scene = std::move(scene);
    dirty_ = true;
    ++changes_;
    overtaken_ = true;
    changed_.notify_all();
    return "";
}

std::string ExploreSession::set_camera_text(const std::string& text) {
    Camera camera;
    try {
        camera = load_camera_text(text, "camera");
    } catch (const std::exception& e) {
        return one_line(e.what());
    }
    std::lock_guard lock(mutex_);
    camera_ = camera;
    pending_.camera = camera;
    dirty_ = true;
    ++changes_;
    overtaken_ = true;
    changed_.notify_all();
    return "";
}

std::string ExploreSession::set_options(const std::vector<std::string>& args) {
    std::vector<const char*> argv{app_.id().c_str(), "--explore"};
    for (const std::string& a : args) argv.push_back(a.c_str());
    ChapterApp::Invocation inv;
    std::string message;
    // Refused before they are parsed: --allow's check would tell whether a folder exists.
    for (const std::string& a : args)
        if (a.starts_with("--allow") || a.starts_with("--no-token"))
            return a.substr(0, a.find('=')) + ": is the command line's: the page cannot widen what it may do";
    if (app_.parse(int(argv.size()), argv.data(), inv, &message)) return message.empty() ? "not an option" : message;
    std::lock_guard lock(mutex_);
    Scene facts;
    facts.antialiasing = scene_antialiasing_;
    facts.samples = scene_samples_;
    try {
        (void)options_for(facts, inv);
    } catch (const std::invalid_argument& e) {
        return one_line(e.what());
    }
    invocation_ = inv;
    pending_.invocation = inv;
    pending_.options = true;
    dirty_ = true;
    ++changes_;
    overtaken_ = true;
    changed_.notify_all();
    return "";
}

std::shared_ptr<const ExploreFrame> ExploreSession::frame_after(std::uint64_t after,
                                                                std::chrono::milliseconds wait) const {
    std::unique_lock lock(mutex_);
    framed_.wait_for(lock, wait, [&] { return stop_ || (frame_ && frame_->id > after); });
    return frame_;
}

json ExploreSession::pick(int x, int y, bool svg) {
    {
        // A click sees the camera of the last move: wait until the render thread has taken
        // the changes made so far (it drops a refining pass for them).
        std::unique_lock wait(mutex_);
        const std::uint64_t made = changes_;
        framed_.wait_for(wait, std::chrono::seconds(10), [&] { return applied_ >= made || stop_; });
    }
    std::shared_lock lock(scene_mutex_);
    if (!scene_) return json{{"error", "the scene is not loaded yet"}};
    try {
        const RenderOptions o = options_for(*scene_, render_invocation_);
        const Pick p = rt::pick(*scene_, o, x, y);
        if (!svg) return pick_json(scene_name_, *scene_, x, y, p);
        if (p.tree.nodes.empty())
            return json{
                {"error", "scene '" + scene_name_ + "' is shaded without a ray tree; use \"shading\": \"whitted\""}};
        // The title and colour --svg gives it.
        return json{
            {"svg", ray_tree_svg(*scene_, p.tree,
                                 scene_name_ + ", pixel " + std::to_string(x) + "," + std::to_string(y), p.color)}};
    } catch (const std::exception& e) {
        return json{{"error", one_line(e.what())}};
    }
}

std::string ExploreSession::render_error() const {
    std::lock_guard lock(mutex_);
    return render_error_;
}

void ExploreSession::publish(std::shared_ptr<ExploreFrame> frame) {
    {
        std::lock_guard lock(mutex_);
        frame_ = std::move(frame);
    }
    framed_.notify_all();
}

void ExploreSession::apply(Settings& taken) {
    // The scene's own depth and structure, unless the command line overrides them.
    int depth;
    AccelKind accel;
    {
        std::lock_guard lock(mutex_);
        depth = scene_depth_;
        accel = scene_accel_;
    }
    bool rebuild = false;
    if (taken.scene) {
        scene_ = std::move(taken.scene);
        rebuild = true;
    }
    if (taken.options) render_invocation_ = taken.invocation;
    const ChapterApp::Invocation& inv = render_invocation_;
    if (taken.camera) scene_->camera = *taken.camera;
    scene_->max_depth = inv.max_depth.value_or(depth);
    const AccelKind want = inv.accel.empty() ? accel : *kAccelNames.find(inv.accel);
    if (rebuild || !scene_->accel || scene_->accel_kind != want) scene_->build_accel(want);
}

void ExploreSession::loop() {
    std::uint64_t generation = 0;
    RenderOptions o;
    int samples = 0;
    bool fresh = false, ready = false;
    bool settle = false;      // the change's first pass made: refine once the view is still
    double full_pass_ms = 0;  // of the last full-size pass: decides the preview's size
    // A pass's time runs from the hand-over of the one before, when this thread goes
    // straight on, or from the change that woke it: all the time between two frames but the
    // wait for work.
    Clock::time_point handed = Clock::now();
    for (;;) {
        Settings taken;
        bool changed = false;
        std::uint64_t taking = 0;
        Clock::time_point pass_start = handed;
        {
            std::unique_lock lock(mutex_);
            const auto work = [&] { return stop_ || dirty_ || (ready && samples < o.spp); };
            if (!work()) {
                changed_.wait(lock, work);
                pass_start = Clock::now();
            }
            if (stop_) return;
            if (dirty_) {
                taken = std::move(pending_);
                pending_ = Settings{};
                dirty_ = false;
                overtaken_ = false;
                changed = true;
                taking = changes_;
            }
        }
        if (changed) {
            std::unique_lock write(scene_mutex_);
            apply(taken);
            {
                std::lock_guard lock(mutex_);
                applied_ = taking;
            }
            framed_.notify_all();  // a pick waiting for these changes
            ++generation;
            try {
                o = options_for(*scene_, render_invocation_);
                ready = true;
            } catch (const std::invalid_argument&) {
                ready = false;  // checked when set: not reached
            }
            o.sample_count = 1;
            samples = 0;
            fresh = true;
            settle = false;
        }
        if (!ready || samples >= o.spp) continue;
        if (settle) {
            settle = false;
            std::unique_lock lock(mutex_);
            const bool moved = changed_.wait_until(lock, handed + kSettle, [&] { return stop_ || dirty_; });
            pass_start = handed = Clock::now();  // waiting is not the pass's time
            if (moved) continue;
        }

        Pass pass;
        pass.generation = generation;
        pass.target_samples = o.spp;
        try {
            // After a change, a pass too slow to follow the mouse is first made at a half or
            // a quarter of the size (sample 0 only), then refined at full size.
            const int shrink = !fresh || full_pass_ms <= kQuickPassMs ? 1 : full_pass_ms <= 4 * kQuickPassMs ? 2 : 4;
            RenderOptions po = o;
            // A pass that refines is dropped for a change; the first after a change is not:
            // while the mouse moves faster than passes finish, each shows a frame.
            po.cancel = fresh ? nullptr : &overtaken_;
            settle = fresh;
            fresh = false;
            po.first_sample = shrink > 1 ? 0 : samples;
            // Each pass its own random numbers (a pixel's streams run in order, so pass k cannot
            // take sample k's numbers of one render): still the same for the same --seed.
            po.seed = o.seed ^ (std::uint64_t(po.first_sample) * 0x9E3779B97F4A7C15ull);
            po.width = std::max(1, o.width / shrink);
            po.height = std::max(1, o.height / shrink);
            std::shared_lock read(scene_mutex_);
            pass.result = render(*scene_, po);
            read.unlock();
            if (po.cancel && overtaken_) continue;  // part of an image of a view that has gone
            pass.preview = shrink > 1;
            if (!pass.preview) {
                full_pass_ms = pass.result.seconds * 1000;
                pass.samples = ++samples;
            }
        } catch (const std::exception& e) {
            // An unfinished exercise, say: the page shows why, and nothing more is tried
            // until something changes.
            {
                std::lock_guard lock(mutex_);
                render_error_ = one_line(e.what());
            }
            framed_.notify_all();
            std::fprintf(stderr, "%s: explore: %s\n", app_.id().c_str(), one_line(e.what()).c_str());
            ready = false;
            continue;
        }
        {
            std::lock_guard lock(mutex_);
            render_error_.clear();
        }
        // On to the finisher, once it has taken the pass before (it takes a few
        // milliseconds; a pass tens): this thread starts the next pass meanwhile.
        std::unique_lock lock(pass_mutex_);
        passed_.wait(lock, [&] { return !pass_; });
        handed = Clock::now();
        pass.pass_ms = std::chrono::duration<double, std::milli>(handed - pass_start).count();
        pass_ = std::move(pass);
        lock.unlock();
        passed_.notify_all();
    }
}

void ExploreSession::finish_loop() {
    std::uint64_t frames = 0, summed = 0;  // frames published; the generation `sum` holds
    std::vector<double> sum;
    for (;;) {
        Pass pass;
        {
            std::unique_lock lock(pass_mutex_);
            passed_.wait(lock, [&] { return finish_stop_ || pass_; });
            if (!pass_) return;  // stopping, and nothing left
            pass = std::move(*pass_);
            pass_.reset();
        }
        passed_.notify_all();  // the render thread may hand on its next
        const auto start = Clock::now();
        auto frame = std::make_shared<ExploreFrame>();
        const RenderResult& r = pass.result;
        frame->generation = pass.generation;
        frame->target_samples = pass.target_samples;
        frame->width = r.image.width;
        frame->height = r.image.height;
        frame->render_ms = r.seconds * 1000;
        frame->pass_ms = pass.pass_ms;
        const double rays = double(r.counters.total());
        frame->mrays_per_s = r.seconds > 0 ? rays / r.seconds / 1e6 : 0;
        frame->nodes_per_ray = rays > 0 ? double(r.counters.nodes_visited) / rays : 0;
        frame->primitives_per_ray = rays > 0 ? double(r.counters.primitives_tested) / rays : 0;
        if (pass.preview) {
            to_rgb(r.image, frame->rgb);
        } else {
            // The first sample of a change starts the sum again.
            const std::size_t size = r.image.pixels.size() * 3;
            if (pass.samples == 1 || summed != pass.generation || sum.size() != size) sum.assign(size, 0.0);
            summed = pass.generation;
            accumulate_to_rgb(r.image, sum, pass.samples, frame->rgb);
        }
        frame->samples = pass.samples;
        frame->finish_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        frame->id = ++frames;
        publish(std::move(frame));
    }
}

}  // namespace rt
