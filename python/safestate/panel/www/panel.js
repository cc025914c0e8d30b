// The operator panel (issue 16, design §11). Speaks docs/operator-link-schema.json (v1) to the
// bridge: shows every status frame, claims control with the token from the URL fragment,
// sends a heartbeat every 50 ms while in control (the core stops a jog 100 ms after the
// last one), and drives the cell simulator's switches.
"use strict";

const HEARTBEAT_MS = 50;
const $ = (id) => document.getElementById(id);
let ws = null;
let nextId = 1;
let inControl = false;
let plant = null;        // the switches as the last status reported them
const nodes = new Map(); // state name -> <g class="node">
const edges = [];        // {row, from, to, g}

function send(msg) {
  if (ws && ws.readyState === WebSocket.OPEN) ws.send(JSON.stringify(Object.assign({ v: 1 }, msg)));
}

function token() {
  const m = /(?:^|[#&])token=([^&]+)/.exec(window.location.hash);
  return m ? decodeURIComponent(m[1]) : null;
}

function command(kind, extra) {
  send(Object.assign({ type: "command", id: nextId++, command: kind }, extra || {}));
}

function setPlant(change) {
  send({ type: "plant", id: nextId++, set: change });
}

function text(id, value) {
  const el = $(id);
  const s = String(value);
  if (el.textContent !== s) el.textContent = s;
}

function onOff(b) { return b ? "ON" : "off"; }

function showStatus(st, link) {
  text("cycle", st.cycle);
  text("state", st.state);
  text("mode", st.selector);
  text("session", st.session_mode);
  text("stop", st.stop_category);
  text("fault", st.fault_code);
  text("reject", st.last_reject_reason);
  text("result", st.command_result);
  text("rows", (st.rows.cycle || "-") + " / " + (st.rows.command || "-"));
  text("out-contactor", onOff(st.outputs.contactor_closed));
  text("out-drive", onOff(st.outputs.drive_enable));
  text("out-brake", onOff(st.outputs.brake_release));
  text("out-ramp", onOff(st.outputs.ramp_down_request));
  text("out-lamp", onOff(st.outputs.reset_lamp));
  text("out-speed", st.outputs.commanded_speed_mm_s);
  st.outputs.axes.forEach((a, i) => text("axis-" + (i + 1), a));
  text("link", st.operator_link_ok ? "heartbeat ok" : "no heartbeat");
  plant = st.plant;
  $("plant-estop").classList.toggle("on", plant.estop_pressed);
  $("plant-stuck").classList.toggle("on", plant.estop_b_stuck_open);
  $("plant-gate").classList.toggle("on", plant.gate_open);
  $("plant-drive-fault").classList.toggle("on", plant.drive_fault);
  for (const r of document.getElementsByName("enabling")) r.checked = r.value === plant.enabling;
  for (const r of document.getElementsByName("selector")) r.checked = r.value === plant.selector;
  highlight(st.state, st.rows.last_transition);
  document.body.dataset.cycle = String(st.cycle);
}

function highlight(state, row) {
  for (const g of nodes.values()) g.classList.remove("current");
  const n = nodes.get(state);
  if (n) n.classList.add("current");
  for (const e of edges) e.g.classList.toggle("fired", e.rows.includes(row) && e.to === state);
}

function loadDiagram() {
  fetch("diagram.svg").then((r) => r.text()).then((svgText) => {
    const box = $("diagram");
    box.innerHTML = svgText.replace(/^[\s\S]*?(<svg)/, "$1");
    for (const g of box.querySelectorAll("g.node")) {
      const t = g.querySelector("title");
      if (t) nodes.set(t.textContent.trim(), g);
    }
    for (const g of box.querySelectorAll("g.edge")) {
      // diagram_dot.py: the edge's id is "rows:" + the ids of the rows it stands for.
      const t = g.querySelector("title");
      if (!t || !g.id.startsWith("rows:")) continue;
      const [from, to] = t.textContent.split("->").map((s) => s.trim());
      edges.push({ rows: g.id.slice("rows:".length).split(","), from, to, g });
    }
    box.dataset.loaded = "true";
  });
}

function connect() {
  ws = new WebSocket(window.location.href.replace(/^http/, "ws").replace(/[#?].*$/, "").replace(/[^/]*$/, "") + "ws");
  ws.onopen = () => {
    text("link", "connected");
    const t = token();
    if (t) send({ type: "request_control", id: nextId++, token: t });
  };
  ws.onmessage = (ev) => {
    const m = JSON.parse(ev.data);
    if (m.type === "status") {
      showStatus(m.status, m.link);
    } else if (m.type === "confirm_control") {
      inControl = true;
      text("control", "in control");
    } else if (m.type === "control_released") {
      inControl = false;
      text("control", "observer (" + m.reason + ")");
    } else if (m.type === "refused") {
      text("answer", m.request + ": " + m.reason);
      if (m.request === "request_control") text("control", "observer (" + m.reason + ")");
    } else if (m.type === "result") {
      text("answer", m.command + ": " + m.result);
    } else if (m.type === "error") {
      text("answer", m.error + ": " + m.detail);
    }
  };
  ws.onclose = () => {
    inControl = false;
    text("link", "closed");
    text("control", "observer");
  };
}

function wire() {
  for (const kind of ["RESET", "SERVO_ON", "SERVO_OFF", "START", "PAUSE", "RESUME", "JOG_STOP", "T2_CONFIRM"]) {
    $("cmd-" + kind).addEventListener("click", () => command(kind));
  }
  $("cmd-JOG_START").addEventListener("click", () => command("JOG_START", {
    axis: parseInt($("jog-axis").value, 10),
    direction: parseInt($("jog-dir").value, 10),
    speed_mm_s: parseInt($("jog-speed").value, 10),
  }));
  $("plant-estop").addEventListener("click", () => setPlant({ estop_pressed: !(plant && plant.estop_pressed) }));
  $("plant-stuck").addEventListener("click", () => setPlant({ estop_b_stuck_open: !(plant && plant.estop_b_stuck_open) }));
  $("plant-gate").addEventListener("click", () => setPlant({ gate_open: !(plant && plant.gate_open) }));
  $("plant-drive-fault").addEventListener("click", () => setPlant({ drive_fault: !(plant && plant.drive_fault) }));
  for (const r of document.getElementsByName("enabling")) r.addEventListener("change", () => setPlant({ enabling: r.value }));
  for (const r of document.getElementsByName("selector")) r.addEventListener("change", () => setPlant({ selector: r.value }));
  setInterval(() => { if (inControl) send({ type: "heartbeat" }); }, HEARTBEAT_MS);
}

wire();
loadDiagram();
connect();
