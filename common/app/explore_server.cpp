#include "app/explore.hpp"

#include "app/explore_gate.hpp"
#include "app/explore_session.hpp"
#include "app/lab_paths.hpp"
#include "core/text.hpp"

#include <httplib.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <optional>
#include <semaphore>
#include <sstream>
#include <utility>

namespace rt {

namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

// What the page may do, said to the browser (Content-Security-Policy): run scripts of this
// server only (none written into the page, none of another site), show images of this server
// and those it makes itself (the ray tree's SVG, fetched with the token), talk to this server
// only, and be shown in no other site's frame.
constexpr const char* kPagePolicy =
    "default-src 'none'; script-src 'self'; style-src 'self'; img-src 'self' blob:; connect-src 'self'; "
    "base-uri 'none'; form-action 'none'; frame-ancestors 'none'";
// Everything else (JSON, the SVG, errors), should a browser be sent to it: nothing runs.
constexpr const char* kDataPolicy = "default-src 'none'; frame-ancestors 'none'; sandbox";

// httplib's pool queues every connection it accepts, without end. This one holds at most
// `workers` at work and as many waiting: past that, the accepting thread waits for a place,
// and new connections wait in the kernel's listen queue, costing the process nothing.
// TaskQueue::enqueue returns nothing in Debian 12's cpp-httplib (0.11) and whether it took the
// task in Debian 13's (0.18): this one always takes it.
using Enqueued = decltype(std::declval<httplib::TaskQueue&>().enqueue(std::function<void()>()));
class BoundedPool final : public httplib::TaskQueue {
public:
    explicit BoundedPool(std::size_t workers) : places_(std::ptrdiff_t(2 * workers)), pool_(workers) {}
    Enqueued enqueue(std::function<void()> fn) override {
        places_.acquire();
        pool_.enqueue([this, fn = std::move(fn)] {
            fn();
            places_.release();
        });
        return static_cast<Enqueued>(true);  // true, or nothing (a void expression) where enqueue is void
    }
    void shutdown() override { pool_.shutdown(); }

private:
    std::counting_semaphore<> places_;
    httplib::ThreadPool pool_;
};

// The page's own files (tools/explore/) and three.js from Debian's libjs-three: served as
// they are, with no build step.
struct StaticFile {
    const char* url;
    std::string path;  // empty: nothing to send (204)
    const char* type;
};

std::string read_whole(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return "";
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void fail(httplib::Response& res, int status, const std::string& message) {
    res.status = status;
    res.set_content(json{{"error", one_line(message)}}.dump(-1, ' ', false, json::error_handler_t::replace),
                    "application/json");
}

// A whole non-negative number, or nothing ("12x", "-1" and "" are not).
std::optional<long long> whole(const std::string& text, long long max) {
    long long v = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (error != std::errc() || end != text.data() + text.size() || text.empty() || v < 0 || v > max)
        return std::nullopt;
    return v;
}

// A query parameter that must be a whole number in [0, max]; answers 400 and returns nothing
// otherwise.
std::optional<long long> number_param(const httplib::Request& req, httplib::Response& res, const char* name,
                                      long long max, std::optional<long long> fallback = std::nullopt) {
    if (!req.has_param(name)) {
        if (!fallback) fail(res, 400, std::string("missing parameter '") + name + "'");
        return fallback;
    }
    const std::string text = req.get_param_value(name);
    const auto v = whole(text, max);
    if (!v)
        fail(res, 400,
             std::string("parameter '") + name + "' must be a whole number in 0.." + std::to_string(max) + ", not '" +
                 text + "'");
    return v;
}

void answer(httplib::Response& res, const std::string& refusal) {
    if (refusal.empty())
        res.set_content("{\"ok\":true}", "application/json");
    else
        fail(res, 400, refusal);
}

}  // namespace

int explore(const ChapterApp& app, const ChapterApp::Invocation& inv) {
    const char* id = app.id().c_str();
    std::unique_ptr<ExploreSession> session;
    try {
        session = std::make_unique<ExploreSession>(app, inv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: error: %s\n", id, one_line(e.what()).c_str());
        return 2;
    }
    ExploreSession& s = *session;

    httplib::Server server;
    // Long-polled frames each hold a worker: enough of them for a few tabs' connections, and
    // no more at once (BoundedPool).
    server.new_task_queue = [] { return new BoundedPool(24); };
    // One request a connection: a request refused before its body was read leaves that body
    // unread, and the connection must close rather than read it as the next request.
    server.set_keep_alive_max_count(1);
    server.set_keep_alive_timeout(2);
    // Not httplib's default SO_REUSEPORT: a second explorer on a taken port is refused, not
    // given half the connections.
    server.set_socket_options([](socket_t sock) {
        int yes = 1;
        setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, reinterpret_cast<const void*>(&yes), sizeof yes);
    });
    server.set_read_timeout(5);
    server.set_payload_max_length(std::size_t(limits::scene_file_bytes.max));

    const std::string page = explore_page_dir();
    const std::vector<StaticFile> files{{"/", page + "/index.html", "text/html; charset=utf-8"},
                                        {"/explore.js", page + "/explore.js", "text/javascript"},
                                        {"/explore.css", page + "/explore.css", "text/css"},
                                        {"/three.min.js", three_js_path(), "text/javascript"},
                                        {"/favicon.ico", "", ""}};
    for (const StaticFile& f : files)
        server.Get(f.url, [f](const httplib::Request&, httplib::Response& res) {
            if (f.path.empty()) return void(res.status = 204);
            const std::string text = read_whole(f.path);
            if (text.empty()) return fail(res, 500, "cannot read " + f.path);
            res.set_header("Cache-Control", "no-cache");
            res.set_header("Content-Security-Policy", kPagePolicy);
            res.set_content(text, f.type);
        });

    // Every request passes the gate (explore_gate.hpp) before anything else is done with it,
    // its body unread; the page's files need no token.
    std::optional<ExploreGate> gate;  // once the port is known
    const auto refused = [&](const httplib::Request& req, httplib::Response& res) {
        const bool page_file =
            std::any_of(files.begin(), files.end(), [&](const StaticFile& f) { return req.path == f.url; });
        const auto refusal = gate->check(req, page_file);
        if (refusal) fail(res, refusal->status, refusal->reason);
        return refusal.has_value();
    };
    server.set_pre_routing_handler([&](const httplib::Request& req, httplib::Response& res) {
        return refused(req, res) ? httplib::Server::HandlerResponse::Handled
                                 : httplib::Server::HandlerResponse::Unhandled;
    });
    // A client that waits for leave to send its body (curl's Expect: 100-continue) is refused
    // before it sends it.
    server.set_expect_100_continue_handler(
        [&](const httplib::Request& req, httplib::Response& res) { return refused(req, res) ? res.status : 100; });
    server.set_post_routing_handler([](const httplib::Request&, httplib::Response& res) {
        if (!res.has_header("Content-Security-Policy")) res.set_header("Content-Security-Policy", kDataPolicy);
        res.set_header("X-Content-Type-Options", "nosniff");  // a JSON error is never read as a page
        res.set_header("Referrer-Policy", "no-referrer");     // the page's address holds the token
        if (!res.has_header("Cache-Control")) res.set_header("Cache-Control", "no-store");  // a pick's answer changes
    });

    server.Get("/api/state", [&](const httplib::Request&, httplib::Response& res) {
        res.set_content(s.state().dump(-1, ' ', false, json::error_handler_t::replace), "application/json");
    });

    // GET /api/frame?after=N[&format=rgb|rgba|png|jpeg][&wait=MS]: the first frame newer than N,
    // waiting up to MS (default 1000) for it: long polling. 204 when there is none yet.
    server.Get("/api/frame", [&](const httplib::Request& req, httplib::Response& res) {
        const auto after = number_param(req, res, "after", std::numeric_limits<long long>::max(), 0);
        const auto wait = number_param(req, res, "wait", 10000, 1000);
        if (!after || !wait) return;
        const std::string name = req.has_param("format") ? req.get_param_value("format") : "rgba";
        const std::optional<FrameFormat> format = kFrameFormatNames.find(name);
        if (!format)
            return fail(res, 400, "parameter 'format' must be " + kFrameFormatNames.list() + ", not '" + name + "'");
        const auto frame = s.frame_after(std::uint64_t(*after), std::chrono::milliseconds(*wait));
        const std::string error = s.render_error();
        if (!error.empty()) res.set_header("X-Render-Error", error);
        if (!frame) {
            res.status = 204;
            return;
        }
        const auto start = Clock::now();
        std::string bytes = encode_frame(*frame, *format);
        const double encode_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        const auto header = [&](const char* key, auto v) { res.set_header(key, std::to_string(v)); };
        header("X-Frame-Id", frame->id);
        header("X-Generation", frame->generation);
        header("X-Width", frame->width);
        header("X-Height", frame->height);
        header("X-Samples", frame->samples);
        header("X-Target-Samples", frame->target_samples);
        header("X-Render-Ms", frame->render_ms);
        header("X-Finish-Ms", frame->finish_ms);
        header("X-Pass-Ms", frame->pass_ms);
        header("X-Encode-Ms", encode_ms);
        header("X-Mrays", frame->mrays_per_s);
        header("X-Nodes-Per-Ray", frame->nodes_per_ray);
        header("X-Primitives-Per-Ray", frame->primitives_per_ray);
        res.set_header("Cache-Control", "no-store");
        res.set_content(std::move(bytes), mime_type(*format));
    });

    // POST /api/scene: a scene file's text; POST /api/camera: its "camera" object alone.
    server.Post("/api/scene",
                [&](const httplib::Request& req, httplib::Response& res) { answer(res, s.set_scene_text(req.body)); });
    server.Post("/api/camera",
                [&](const httplib::Request& req, httplib::Response& res) { answer(res, s.set_camera_text(req.body)); });
    // POST /api/options: a JSON array of command-line arguments, ["--spp", "4", ...].
    server.Post("/api/options", [&](const httplib::Request& req, httplib::Response& res) {
        const json args = json::parse(req.body, nullptr, false);
        if (!args.is_array()) return fail(res, 400, "options: the body must be a JSON array of strings");
        std::vector<std::string> list;
        for (const json& a : args) {
            if (!a.is_string()) return fail(res, 400, "options: the body must be a JSON array of strings");
            list.push_back(a.get<std::string>());
        }
        answer(res, s.set_options(list));
    });
    // GET /api/pick?x=X&y=Y: what --pick X,Y prints; GET /api/tree.svg?x=X&y=Y: what --svg draws.
    const auto pick = [&](const httplib::Request& req, httplib::Response& res, bool svg) {
        const auto x = number_param(req, res, "x", limits::image_side.max);
        if (!x) return;
        const auto y = number_param(req, res, "y", limits::image_side.max);
        if (!y) return;
        const json j = s.pick(int(*x), int(*y), svg);
        if (j.contains("error")) return fail(res, 400, j["error"].get<std::string>());
        if (svg) return res.set_content(j["svg"].get<std::string>(), "image/svg+xml");
        res.set_content(j.dump(-1, ' ', false, json::error_handler_t::replace), "application/json");
    };
    server.Get("/api/pick", [&](const httplib::Request& req, httplib::Response& res) { pick(req, res, false); });
    server.Get("/api/tree.svg", [&](const httplib::Request& req, httplib::Response& res) { pick(req, res, true); });

    server.set_error_handler([](const httplib::Request& req, httplib::Response& res) {
        if (res.status == 404)
            fail(res, 404, "no such page: " + req.method + " " + req.path);
        else if (res.body.empty())
            fail(res, res.status, "request refused (HTTP " + std::to_string(res.status) + ")");
    });
    server.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr e) {
        try {
            std::rethrow_exception(e);
        } catch (const std::exception& x) {
            fail(res, 500, x.what());
        } catch (...) {
            fail(res, 500, "unknown error");
        }
    });

    // Loopback only, and the gate: the explorer runs the student's code on whatever a page posts.
    const int port = inv.port == 0 ? server.bind_to_any_port("127.0.0.1")
                                   : (server.bind_to_port("127.0.0.1", inv.port) ? inv.port : -1);
    if (port <= 0) {
        std::fprintf(stderr, "%s: error: --port %d: cannot listen on 127.0.0.1 (in use?)\n", id, inv.port);
        return 2;
    }
    std::string token;
    try {
        token = inv.no_token ? "" : new_explore_token();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: error: %s\n", id, one_line(e.what()).c_str());
        return 2;
    }
    gate.emplace(port, token);
    std::printf("%s: the explorer is at %s (Ctrl-C ends it)\n", id, gate->address().c_str());
    std::fflush(stdout);
    if (inv.no_token)
        std::fprintf(stderr, "%s: --no-token: any program on this machine may drive this explorer (for tests only)\n",
                     id);
    server.listen_after_bind();
    return 0;
}

}  // namespace rt
