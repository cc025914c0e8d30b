// SPDX-License-Identifier: Apache-2.0
// The operator link's bridge (design §11): Boost.Beast WebSocket + HTTP on 127.0.0.1,
// nlohmann-json for the messages of docs/operator-link-schema.json. One io_context, run by
// one thread: every handler below runs on that thread, so the bridge state needs no locks.
#include "safestate/link/bridge.hpp"

#include <sys/stat.h>

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <deque>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>
#include <utility>

#include "safestate/command_kind.hpp"
#include "safestate/enum_strings.hpp"
#include "safestate/transition_table.hpp"

namespace safestate::link {

namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
namespace net = boost::asio;
using tcp = net::ip::tcp;
using json = nlohmann::json;
using Clock = std::chrono::steady_clock;

bool read_token_file(const std::filesystem::path& path, std::string& token, std::string& error) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    error = path.string() + ": cannot read the token file (it does not exist)";
    return false;
  }
  if (!S_ISREG(st.st_mode)) {
    error = path.string() + ": the token file is not a regular file";
    return false;
  }
  if ((st.st_mode & 077U) != 0) {
    std::ostringstream mode;
    mode << std::oct << (st.st_mode & 0777U);
    error = path.string() + ": the token file is readable by others (mode 0" + mode.str() +
            "); expected mode 0600 (chmod 600 " + path.string() + ")";
    return false;
  }
  std::ifstream in(path);
  std::getline(in, token);
  while (!token.empty() && (token.back() == '\r' || token.back() == ' ' || token.back() == '\n')) token.pop_back();
  if (token.empty()) {
    error = path.string() + ":1:1: the token file is empty; expected a token on its first line";
    return false;
  }
  return true;
}

namespace {

using Frame = std::shared_ptr<const std::string>;

Frame frame(const json& j) { return std::make_shared<const std::string>(j.dump()); }

json message(std::string_view type, const json& id) {
  json j{{"v", kLinkSchemaVersion}, {"type", type}};
  if (!id.is_null()) j["id"] = id;
  return j;
}

std::string_view content_type(const std::filesystem::path& p) {
  const std::string ext = p.extension().string();
  if (ext == ".html") return "text/html; charset=utf-8";
  if (ext == ".js") return "text/javascript; charset=utf-8";
  if (ext == ".css") return "text/css; charset=utf-8";
  if (ext == ".svg") return "image/svg+xml";
  if (ext == ".json") return "application/json";
  return "application/octet-stream";
}

std::string_view row_id(std::int16_t index) {
  if (index < 0 || static_cast<std::size_t>(index) >= kTransitionTable.size()) return {};
  return kTransitionTable[static_cast<std::size_t>(index)].id;
}

json status_json(const CellStatus& c) {
  const StatusRecord& s = c.status;
  json axes = json::array();
  for (const AxisState a : c.outputs.axes) axes.push_back(to_string(a));
  const PlantSwitches p = PlantSwitches::unpack(c.plant_switches);
  const std::string_view cycle_row = row_id(c.cycle_row);
  const std::string_view command_row = row_id(c.command_row);
  const std::string_view transition_row = row_id(c.last_transition_row);
  json recent = json::array();
  for (std::size_t i = 0; i < c.recent.size(); ++i) {
    const CellStatus::Transition& t = c.recent[(c.recent_next + i) % c.recent.size()];
    if (t.row < 0) continue;
    recent.push_back(
        {{"cycle", t.cycle}, {"row", row_id(t.row)}, {"from", to_string(t.from)}, {"to", to_string(t.to)}});
  }
  return json{
      {"cycle", c.cycle},
      {"state", to_string(s.state)},
      {"selector", to_string(s.selector)},
      {"session_mode", to_string(s.session_mode)},
      {"stop_category", to_string(s.stop_category)},
      {"fault_code", to_string(s.fault_code)},
      {"last_reject_reason", to_string(s.last_reject_reason)},
      {"command_result", to_string(s.command_result)},
      {"queue_length", s.queue_length},
      {"jog", {{"axis", s.jog_axis}, {"direction", s.jog_direction}, {"speed_mm_s", s.jog_speed_mm_s}}},
      {"estop_mismatch", s.estop_mismatch},
      {"outputs",
       {{"contactor_closed", c.outputs.contactor_closed},
        {"drive_enable", c.outputs.drive_enable},
        {"brake_release", c.outputs.brake_release},
        {"ramp_down_request", c.outputs.ramp_down_request},
        {"reset_lamp", c.outputs.reset_lamp},
        {"commanded_speed_mm_s", c.outputs.commanded_speed_mm_s},
        {"axes", axes}}},
      {"rows",
       {{"cycle", cycle_row.empty() ? json(nullptr) : json(cycle_row)},
        {"command", command_row.empty() ? json(nullptr) : json(command_row)},
        {"last_transition", transition_row.empty() ? json(nullptr) : json(transition_row)},
        {"last_transition_from", to_string(c.last_transition_from)}}},
      {"plant",
       {{"estop_pressed", p.estop_pressed},
        {"estop_b_stuck_open", p.estop_b_stuck_open},
        {"gate_open", p.gate_open},
        {"enabling", to_string(p.enabling)},
        {"selector", to_string(p.selector)},
        {"drive_fault", p.drive_fault}}},
      {"operator_link_ok", c.operator_link_ok},
      {"heartbeat_age_cycles", c.heartbeat_age_cycles},
      {"recent_transitions", recent},
  };
}

template <typename E, std::size_t N>
std::optional<E> enum_field(const json& j, const char* key, const std::array<E, N>& all) {
  if (!j.contains(key) || !j[key].is_string()) return std::nullopt;
  return enum_from_string(j[key].get<std::string>(), all);
}

std::optional<std::int32_t> int32_field(const json& j, const char* key) {
  if (!j.contains(key) || !j[key].is_number_integer()) return std::nullopt;
  const auto v = j[key].get<std::int64_t>();
  if (v < std::numeric_limits<std::int32_t>::min() || v > std::numeric_limits<std::int32_t>::max()) return std::nullopt;
  return static_cast<std::int32_t>(v);
}

}  // namespace

class WsSession;

struct Bridge::Impl {
  Impl(ControlLoop& l, BridgeOptions o) : loop(l), opts(std::move(o)), acceptor(ioc), poll(ioc) {
    const tcp::endpoint ep(net::ip::make_address("127.0.0.1"), opts.port);
    acceptor.open(ep.protocol());
    acceptor.set_option(net::socket_base::reuse_address(true));
    acceptor.bind(ep);
    acceptor.listen();
  }

  ControlLoop& loop;
  BridgeOptions opts;
  BridgeCounters counters;
  net::io_context ioc{1};
  tcp::acceptor acceptor;
  net::steady_timer poll;
  std::set<std::shared_ptr<WsSession>> sessions;
  std::uint64_t next_client_id{1};
  WsSession* controller{nullptr};
  Clock::time_point last_heartbeat{};
  Clock::time_point last_status{};
  struct Pending {
    std::uint64_t seq;
    std::weak_ptr<WsSession> client;
    json id;
    CommandKind kind;
  };
  std::deque<Pending> pending;  // bounded by the command queue's capacity
  std::uint64_t queued{0};      // commands queued so far (= seq of the last one)

  void accept();
  void tick();
  void broadcast_status();
  void handle(const std::shared_ptr<WsSession>& s, const std::string& text);
  void on_closed(WsSession* s);
  void release_control(WsSession* s, std::string_view why);
  json link_json() const;
};

class WsSession : public std::enable_shared_from_this<WsSession> {
 public:
  WsSession(tcp::socket&& socket, Bridge::Impl& bridge, std::uint64_t id)
      : ws_(std::move(socket)), bridge_(bridge), id_(id) {}

  void start(http::request<http::string_body> req) {
    // A small kernel send buffer: a client that stops reading is noticed (and its memory
    // bounded) after a few frames, not after megabytes.
    beast::error_code ignored;
    beast::get_lowest_layer(ws_).socket().set_option(net::socket_base::send_buffer_size(16 * 1024), ignored);
    ws_.read_message_max(bridge_.opts.max_frame_bytes);
    ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
    ws_.async_accept(req, [self = shared_from_this()](beast::error_code ec) {
      if (ec) return self->closed();
      self->open_ = true;
      self->send(frame([&] {
                   json j = message("hello", nullptr);
                   j["client_id"] = self->id_;
                   j["role"] = "observer";
                   j["heartbeat_period_ms"] = kHeartbeatPeriodCycles;  // 1 ms cycles
                   j["control_lease_ms"] = self->bridge_.opts.control_lease.count();
                   j["max_frame_bytes"] = self->bridge_.opts.max_frame_bytes;
                   return j;
                 }()),
                 false);
      self->read();
    });
  }

  /// Queues a frame. A status frame (`droppable`) is dropped when max_queued_frames are
  /// waiting; replies are kept (reading from the client pauses at kPauseReadingAt queued
  /// frames, so its requests wait in TCP), and beyond kMaxQueuedReplies the client is closed.
  void send(Frame f, bool droppable) {
    if (closed_ || !open_) return;
    if (droppable && out_.size() >= bridge_.opts.max_queued_frames) {
      bridge_.counters.status_frames_dropped.fetch_add(1);
      return;
    }
    if (out_.size() >= kMaxQueuedReplies) {
      bridge_.counters.slow_consumers_closed.fetch_add(1);
      return abort();
    }
    out_.push_back(std::move(f));
    if (!writing_) write();
  }

  void abort() {
    if (closed_) return;
    beast::error_code ignored;
    beast::get_lowest_layer(ws_).socket().shutdown(tcp::socket::shutdown_both, ignored);
    beast::get_lowest_layer(ws_).socket().close(ignored);
    closed();
  }

  [[nodiscard]] std::uint64_t id() const noexcept { return id_; }

  /// TRUE while kPauseReadingAt or more frames wait to be sent to this client.
  [[nodiscard]] bool backlogged() const noexcept { return out_.size() >= kPauseReadingAt; }

  /// A request of this client that was not executed because its answers are backed up: it
  /// is answered, together with the others, by one `busy` frame once the backlog drains.
  void drop_busy(const json& id) {
    ++busy_dropped_;
    busy_last_id_ = id;
  }

 private:
  void read() {
    reading_ = true;
    ws_.async_read(buffer_, [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec) {
        if (ec == websocket::error::message_too_big) self->bridge_.counters.frame_too_large.fetch_add(1);
        return self->closed();
      }
      const std::string text = beast::buffers_to_string(self->buffer_.data());
      self->buffer_.consume(self->buffer_.size());
      self->bridge_.handle(self, text);
      if (self->closed_) return;
      // Backpressure: an observer's requests wait in TCP. The controlling client is always
      // read, so that its heartbeats never queue behind its own requests (Impl::handle
      // answers those with `busy` while its backlog lasts).
      if (self->backlogged() && self->bridge_.controller != self.get()) {
        self->reading_ = false;
        self->bridge_.counters.reads_paused.fetch_add(1);
        return;
      }
      self->read();
    });
  }

  void write() {
    writing_ = true;
    ws_.text(true);
    ws_.async_write(net::buffer(*out_.front()), [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec) return self->closed();
      self->out_.pop_front();
      if (!self->closed_ && self->out_.size() < kPauseReadingAt / 4) {
        if (self->busy_dropped_ > 0) self->send_busy();
        if (!self->reading_) self->read();
      }
      if (self->out_.empty() || self->closed_) {
        self->writing_ = false;
      } else {
        self->write();
      }
    });
  }

  void send_busy() {
    json j = message("busy", busy_last_id_);
    j["dropped"] = busy_dropped_;
    j["detail"] = "requests not executed: your answers were not read (more than " + std::to_string(kPauseReadingAt) +
                  " waiting); id is the last one's";
    busy_dropped_ = 0;
    busy_last_id_ = json();
    out_.push_back(frame(j));
  }

  void closed() {
    if (closed_) return;
    closed_ = true;
    out_.clear();
    bridge_.on_closed(this);
  }

  websocket::stream<beast::tcp_stream> ws_;
  Bridge::Impl& bridge_;
  std::uint64_t id_;
  beast::flat_buffer buffer_;
  std::deque<Frame> out_;
  bool open_{false};     // handshake done: frames may be written
  bool reading_{false};  // a read is pending (FALSE while paused by backpressure)
  bool writing_{false};
  bool closed_{false};
  std::uint64_t busy_dropped_{0};  // requests answered by the next `busy` frame
  json busy_last_id_;
  static constexpr std::size_t kPauseReadingAt = 64;
  static constexpr std::size_t kMaxQueuedReplies = 1024;
};

namespace {

/// Plain HTTP: the panel's static files from BridgeOptions::www, or the WebSocket upgrade.
class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(tcp::socket&& socket, Bridge::Impl& bridge) : stream_(std::move(socket)), bridge_(bridge) {}

  void start() { read(); }

 private:
  void read() {
    req_ = {};
    parser_.emplace();
    parser_->body_limit(bridge_.opts.max_frame_bytes);
    stream_.expires_after(std::chrono::seconds(30));
    http::async_read(stream_, buffer_, *parser_, [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec) return;
      self->req_ = self->parser_->release();
      if (websocket::is_upgrade(self->req_)) {
        if (self->bridge_.sessions.size() >= self->bridge_.opts.max_clients) {
          self->bridge_.counters.clients_refused.fetch_add(1);
          return self->reply(http::status::service_unavailable, "text/plain", "too many clients\n");
        }
        beast::get_lowest_layer(self->stream_).expires_never();
        auto ws =
            std::make_shared<WsSession>(self->stream_.release_socket(), self->bridge_, self->bridge_.next_client_id++);
        self->bridge_.sessions.insert(ws);
        self->bridge_.counters.clients.store(self->bridge_.sessions.size());
        return ws->start(std::move(self->req_));
      }
      self->serve();
    });
  }

  void serve() {
    if (req_.method() != http::verb::get && req_.method() != http::verb::head) {
      return reply(http::status::method_not_allowed, "text/plain", "only GET\n");
    }
    std::string target(req_.target());
    if (const auto q = target.find('?'); q != std::string::npos) target.resize(q);
    if (target == "/") target = "/index.html";
    // One file name, no directories: nothing outside the www folder can be named.
    const std::string name = target.substr(1);
    const bool plain = !name.empty() &&
                       name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-.") ==
                           std::string::npos &&
                       name[0] != '.';
    const std::filesystem::path file = bridge_.opts.www / name;
    std::ifstream in(file, std::ios::binary);
    if (bridge_.opts.www.empty() || !plain || !in) {
      return reply(http::status::not_found, "text/plain", "not found\n");
    }
    std::ostringstream body;
    body << in.rdbuf();
    reply(http::status::ok, content_type(file), body.str());
  }

  void reply(http::status status, std::string_view type, std::string body) {
    auto res = std::make_shared<http::response<http::string_body>>(status, req_.version());
    res->set(http::field::content_type, beast::string_view(type.data(), type.size()));
    res->set(http::field::cache_control, "no-store");
    res->keep_alive(req_.keep_alive());
    res->body() = std::move(body);
    res->prepare_payload();
    http::async_write(stream_, *res, [self = shared_from_this(), res](beast::error_code ec, std::size_t) {
      if (ec || !res->keep_alive()) {
        beast::error_code ignored;
        self->stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
        return;
      }
      self->read();
    });
  }

  beast::tcp_stream stream_;
  Bridge::Impl& bridge_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
  http::request<http::string_body> req_;
};

}  // namespace

void Bridge::Impl::accept() {
  acceptor.async_accept(ioc, [this](beast::error_code ec, tcp::socket socket) {
    if (ec == net::error::operation_aborted) return;
    if (!ec) std::make_shared<HttpSession>(std::move(socket), *this)->start();
    accept();
  });
}

json Bridge::Impl::link_json() const {
  const BridgeCounters& c = counters;
  return json{
      {"clients", c.clients.load()},
      {"controller_id", controller == nullptr ? json(nullptr) : json(controller->id())},
      {"requests", c.requests.load()},
      {"malformed_json", c.malformed_json.load()},
      {"unknown_type", c.unknown_type.load()},
      {"bad_field", c.bad_field.load()},
      {"frame_too_large", c.frame_too_large.load()},
      {"observer_commands_refused", c.observer_commands_refused.load()},
      {"control_refused", c.control_refused.load()},
      {"queue_full", c.queue_full.load()},
      {"status_frames_dropped", c.status_frames_dropped.load()},
      {"slow_consumers_closed", c.slow_consumers_closed.load()},
      {"clients_refused", c.clients_refused.load()},
      {"results_lost", c.results_lost.load()},
      {"heartbeats", c.heartbeats.load()},
      {"control_lease_expired", c.control_lease_expired.load()},
      {"reads_paused", c.reads_paused.load()},
      {"busy", c.busy.load()},
  };
}

void Bridge::Impl::broadcast_status() {
  CellStatus c;
  if (!loop.read_status(c)) return;
  json j = message("status", nullptr);
  j["status"] = status_json(c);
  j["link"] = link_json();
  const Frame f = frame(j);
  for (const auto& s : sessions) s->send(f, true);
}

// Every millisecond: results of popped commands, the control lease, the status period.
void Bridge::Impl::tick() {
  CommandOutcome o;
  while (loop.pop_outcome(o)) {
    while (!pending.empty() && pending.front().seq < o.seq) {  // the cycle's result queue overflowed
      counters.results_lost.fetch_add(1);
      if (auto s = pending.front().client.lock()) {
        json j = message("result", pending.front().id);
        j["command"] = to_string(pending.front().kind);
        j["result"] = "RESULT_LOST";
        s->send(frame(j), false);
      }
      pending.pop_front();
    }
    if (!pending.empty() && pending.front().seq == o.seq) {
      if (auto s = pending.front().client.lock()) {
        json j = message("result", pending.front().id);
        j["command"] = to_string(pending.front().kind);
        j["result"] = to_string(o.result);
        s->send(frame(j), false);
      }
      pending.pop_front();
    }
  }
  const auto now = Clock::now();
  if (controller != nullptr && now - last_heartbeat > opts.control_lease) {
    counters.control_lease_expired.fetch_add(1);
    release_control(controller, "HEARTBEAT_LOST");
  }
  if (now - last_status >= opts.status_period) {
    last_status = now;
    broadcast_status();
  }
  poll.expires_after(std::chrono::milliseconds(1));
  poll.async_wait([this](beast::error_code ec) {
    if (!ec) tick();
  });
}

void Bridge::Impl::release_control(WsSession* s, std::string_view why) {
  if (controller != s || s == nullptr) return;
  controller = nullptr;
  for (const auto& p : sessions) {
    if (p.get() == s) {
      json j = message("control_released", nullptr);
      j["reason"] = why;
      p->send(frame(j), false);
    }
  }
}

void Bridge::Impl::on_closed(WsSession* s) {
  if (controller == s) controller = nullptr;  // the heartbeat stops with it: C26 within the period
  for (auto it = sessions.begin(); it != sessions.end(); ++it) {
    if (it->get() == s) {
      // Keep the session alive until its pending handlers have run.
      net::post(ioc, [keep = *it] { (void)keep; });
      sessions.erase(it);
      break;
    }
  }
  counters.clients.store(sessions.size());
}

void Bridge::Impl::handle(const std::shared_ptr<WsSession>& s, const std::string& text) {
  counters.requests.fetch_add(1);
  const auto error = [&](std::atomic<std::uint64_t>& counter, std::string_view code, const json& id,
                         const std::string& detail) {
    counter.fetch_add(1);
    json j = message("error", id);
    j["error"] = code;
    j["detail"] = detail;
    s->send(frame(j), false);
  };
  const json req = json::parse(text, nullptr, false);
  if (controller == s.get() && s->backlogged()) {
    // Heartbeats and release_control are handled; everything else waits for no one: it
    // is counted and answered by one `busy` frame when the client has read its answers.
    const bool keeps =
        req.is_object() && req.contains("type") && (req["type"] == "heartbeat" || req["type"] == "release_control");
    if (!keeps) {
      counters.busy.fetch_add(1);
      const bool has_id =
          req.is_object() && req.contains("id") && (req["id"].is_number_integer() || req["id"].is_string());
      s->drop_busy(has_id ? req["id"] : json());
      return;
    }
  }
  if (req.is_discarded() || !req.is_object()) {
    return error(counters.malformed_json, "MALFORMED_JSON", nullptr,
                 req.is_discarded() ? "the frame is not JSON" : "expected a JSON object");
  }
  const json id = req.contains("id") && (req["id"].is_number_integer() || req["id"].is_string()) ? req["id"] : json();
  if (req.contains("v") && req["v"] != kLinkSchemaVersion) {
    return error(
        counters.bad_field, "UNSUPPORTED_VERSION", id,
        "schema version " + req["v"].dump() + " is not supported; expected " + std::to_string(kLinkSchemaVersion));
  }
  if (!req.contains("type") || !req["type"].is_string()) {
    return error(counters.bad_field, "BAD_FIELD", id, "expected a string field 'type'");
  }
  const std::string type = req["type"].get<std::string>();
  const bool controls = controller == s.get();
  const auto refuse = [&](std::atomic<std::uint64_t>& counter, std::string_view reason) {
    counter.fetch_add(1);
    json j = message("refused", id);
    j["request"] = type;
    j["reason"] = reason;
    s->send(frame(j), false);
  };

  if (type == "request_control") {
    if (controls) {
      s->send(frame(message("confirm_control", id)), false);
      return;
    }
    if (!req.contains("token") || !req["token"].is_string() || req["token"].get<std::string>() != opts.token) {
      return refuse(counters.control_refused, "BAD_TOKEN");
    }
    if (controller != nullptr) return refuse(counters.control_refused, "CONTROL_HELD_BY_OTHER");
    controller = s.get();
    last_heartbeat = Clock::now();
    loop.heartbeat().beat();
    s->send(frame(message("confirm_control", id)), false);
    return;
  }
  if (type == "release_control") {
    if (!controls) return refuse(counters.observer_commands_refused, "NO_CONTROL");
    release_control(s.get(), "RELEASED");
    return;
  }
  if (type == "heartbeat") {
    if (!controls) return refuse(counters.observer_commands_refused, "NO_CONTROL");
    counters.heartbeats.fetch_add(1);
    last_heartbeat = Clock::now();
    loop.heartbeat().beat();
    return;  // no reply: heartbeats are frequent
  }
  if (type == "command") {
    const auto kind = enum_field(req, "command", kAllCommandKinds);
    if (!kind) {
      return error(counters.bad_field, "BAD_FIELD", id,
                   "expected 'command': one of RESET, SERVO_ON, SERVO_OFF, START, PAUSE, RESUME, JOG_START, "
                   "JOG_STOP, T2_CONFIRM");
    }
    Command c{*kind, 0, 0, 0};
    if (*kind == CommandKind::JogStart) {
      const auto axis = int32_field(req, "axis");
      const auto dir = int32_field(req, "direction");
      const auto speed = int32_field(req, "speed_mm_s");
      if (!axis || !dir || !speed) {
        return error(counters.bad_field, "BAD_FIELD", id,
                     "JOG_START expects integer fields 'axis', 'direction', 'speed_mm_s' (32-bit)");
      }
      c = Command::jog_start(*axis, *dir, *speed);
    }
    if (!controls) return refuse(counters.observer_commands_refused, "NO_CONTROL");
    if (loop.submit(c) == SubmitResult::queue_full) {
      counters.queue_full.fetch_add(1);
      json j = message("result", id);
      j["command"] = to_string(*kind);
      j["result"] = "QUEUE_FULL";
      s->send(frame(j), false);
      return;
    }
    pending.push_back(Pending{++queued, s, id, *kind});
    return;
  }
  if (type == "plant") {
    if (!controls) return refuse(counters.observer_commands_refused, "NO_CONTROL");
    if (!req.contains("set") || !req["set"].is_object()) {
      return error(counters.bad_field, "BAD_FIELD", id, "expected an object field 'set'");
    }
    const json& set = req["set"];
    PlantSwitches p = loop.plant();
    for (const auto& [key, value] : set.items()) {
      bool ok = true;
      if (key == "estop_pressed" && value.is_boolean()) p.estop_pressed = value.get<bool>();
      else if (key == "estop_b_stuck_open" && value.is_boolean()) p.estop_b_stuck_open = value.get<bool>();
      else if (key == "gate_open" && value.is_boolean()) p.gate_open = value.get<bool>();
      else if (key == "drive_fault" && value.is_boolean()) p.drive_fault = value.get<bool>();
      else if (key == "enabling") {
        const auto e = enum_field(set, "enabling", kAllEnablePositions);
        ok = e.has_value();
        if (ok) p.enabling = *e;
      } else if (key == "selector") {
        const auto m = enum_field(set, "selector", kAllSelectorReadings);
        ok = m.has_value() && *m != SelectorReading::Invalid;
        if (ok) p.selector = *m;
      } else {
        ok = false;
      }
      if (!ok) {
        return error(counters.bad_field, "BAD_FIELD", id,
                     "plant switch '" + key +
                         "': expected estop_pressed, estop_b_stuck_open, gate_open, "
                         "drive_fault (booleans), enabling (RELEASED|MIDDLE|PANIC) or selector (AUTO|T1|T2)");
      }
    }
    loop.set_plant(p);
    s->send(frame(message("plant_set", id)), false);
    return;
  }
  error(counters.unknown_type, "UNKNOWN_TYPE", id,
        "unknown request type '" + type + "'; expected request_control, release_control, heartbeat, command or plant");
}

Bridge::Bridge(ControlLoop& loop, BridgeOptions options) : impl_(std::make_unique<Impl>(loop, std::move(options))) {}

Bridge::~Bridge() = default;

unsigned short Bridge::port() const noexcept { return impl_->acceptor.local_endpoint().port(); }

void Bridge::run() {
  impl_->accept();
  impl_->tick();
  impl_->ioc.run();
}

void Bridge::stop() {
  net::post(impl_->ioc, [this] {
    beast::error_code ignored;
    impl_->acceptor.close(ignored);
    impl_->poll.cancel();
    for (const auto& s : std::set<std::shared_ptr<WsSession>>(impl_->sessions)) s->abort();
    impl_->ioc.stop();
  });
}

const BridgeCounters& Bridge::counters() const noexcept { return impl_->counters; }

}  // namespace safestate::link
