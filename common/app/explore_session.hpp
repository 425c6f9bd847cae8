#pragma once
// The explorer's state: one scene, one camera, one set of options, and the thread that
// renders them progressively into a shared frame buffer (the course's FAQ: "multiple CPUs
// with a shared frame buffer"). The page's requests change them; the render thread applies
// each change between passes, under an exclusive lock; a pass, and a pick, read the scene
// under a shared one. So a pick never waits for a pass, and nothing a pass reads changes
// under it. Each pass rendered goes on to a second thread, the finisher, which adds it to
// the running sum, makes the 8-bit frame and publishes it while the next pass renders: a
// frame's interval is its pass, not the pass and the finishing added.
#include "app/app.hpp"
#include "app/explore_frame.hpp"
#include "io/file_access.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <shared_mutex>
#include <string>
#include <thread>
#include <vector>

namespace rt {

class ExploreSession {
public:
    // Loads the invocation's scene (throws what the loader throws) and starts rendering.
    ExploreSession(const ChapterApp& app, const ChapterApp::Invocation& invocation);
    ~ExploreSession();
    ExploreSession(const ExploreSession&) = delete;
    ExploreSession& operator=(const ExploreSession&) = delete;

    // What the page shows and starts from: the chapter, the scene (and its file's text),
    // the camera, the options, which exercises the program runs, the choices of each control.
    nlohmann::json state() const;

    // Each returns "" once the change is taken, else the one line that refuses it (the
    // loader's FILE:LINE:COL: /pointer: message, or the command line's), changing nothing.
    // A scene sent by the page names files only under page_files() (book §0.11).
    std::string set_scene_text(const std::string& text);
    std::string set_camera_text(const std::string& text);
    // Command-line options (--spp 4 --accel bvh-sah ...), read by the chapter's own parser;
    // not --allow or --no-token, which only the person gives, on the command line.
    std::string set_options(const std::vector<std::string>& args);

    // The newest frame once it is newer than `after`, or the newest there is after `wait`
    // (null before the first).
    std::shared_ptr<const ExploreFrame> frame_after(std::uint64_t after, std::chrono::milliseconds wait) const;

    // What --pick prints for pixel (x, y) of the full-size view, or an "error" line. With
    // `svg`, only the ray tree's side view as --svg draws it, as "svg" (the page asks for it
    // apart: for a scene of many surfaces it takes longer than the pick).
    nlohmann::json pick(int x, int y, bool svg = false);

    // Why the last pass failed (an unfinished exercise, say), or "" while passes succeed.
    std::string render_error() const;

private:
    struct Settings {  // what the page changes
        ChapterApp::Invocation invocation;
        std::shared_ptr<Scene> scene;  // a new one, not yet taken by the render thread
        std::optional<Camera> camera;
        bool options = false;
    };
    // A pass rendered, handed from the render thread to the finisher.
    struct Pass {
        std::uint64_t generation = 0;
        bool preview = false;  // smaller than the view, after a change: shown, not summed
        int samples = 0;       // full-size passes of this generation so far, this one included
        int target_samples = 0;
        double pass_ms = 0;  // the render thread's time for it: render() and all around it
        RenderResult result;
    };
    void loop();
    void finish_loop();             // the finisher
    void apply(Settings& pending);  // render thread
    RenderOptions options_for(const Scene& scene, const ChapterApp::Invocation& inv) const;
    void publish(std::shared_ptr<ExploreFrame> frame);

    const ChapterApp& app_;
    std::string scene_name_, scene_file_, scene_text_, base_dir_;
    // The files a scene from the page may name: the chapter's scene folders, the lab's shared
    // assets and --allow's folders.
    FileAccess page_files_;

    mutable std::mutex mutex_;
    mutable std::condition_variable changed_;  // the render thread waits on it
    mutable std::condition_variable framed_;   // frame_after waits on it
    Settings pending_;
    bool dirty_ = false, stop_ = false;
    std::uint64_t changes_ = 0, applied_ = 0;  // changes made, and taken into the scene
    std::atomic<bool> overtaken_{false};       // a change is waiting: the pass under way stops early
    std::shared_ptr<const ExploreFrame> frame_;
    std::string render_error_;
    ChapterApp::Invocation invocation_;  // as last set (the render thread's may lag a pass)
    Camera camera_;                      // as last set
    Antialiasing scene_antialiasing_;
    int scene_samples_ = 0, scene_depth_ = 0;
    AccelKind scene_accel_ = AccelKind::fast;

    // Written by the render thread only, under an exclusive lock of scene_mutex_.
    mutable std::shared_mutex scene_mutex_;
    std::shared_ptr<Scene> scene_;
    ChapterApp::Invocation render_invocation_;
    std::thread thread_;

    // The hand-over: one pass at most waits for the finisher (the render thread waits for
    // the slot, so a slow finisher slows the passes instead of queueing them).
    std::mutex pass_mutex_;
    std::condition_variable passed_;  // a pass put in the slot, or taken out
    std::optional<Pass> pass_;
    bool finish_stop_ = false;
    std::thread finisher_;
};

}  // namespace rt
