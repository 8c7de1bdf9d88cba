// The dashboard's page (docs/dashboard.md): the Fleet view at "/", a Job view at "/job/ID"; each
// view is one full page load, so the back button and a reload work at any time, and the fleet's
// filter and sort live in the URL's query. Live data comes as Server-Sent Events from cyclopt-web
// (web/dashboard_server.hpp). Every text from a job is put into the page with textContent, never
// parsed as HTML.
"use strict";

// --- helpers -------------------------------------------------------------------------------------

// An element with attributes and text (never HTML).
function el(tag, attributes, text) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attributes || {})) e.setAttribute(k, v);
  if (text !== undefined && text !== null) e.textContent = String(text);
  return e;
}

// As `cyclopt top`: "42%" rounded down, ">=42%" for a lower bound, "?" when unknown.
function percentText(percent, lowerBound) {
  if (percent === null || percent === undefined) return "?";
  return (lowerBound ? ">=" : "") + Math.floor(percent) + "%";
}

// "42 s", "3:05", "1:02:05"; "?" when unknown (service/progress_meter.hpp's clock_text).
function durationText(seconds) {
  if (seconds === null || seconds === undefined || !(seconds >= 0)) return "?";
  const s = Math.round(seconds);
  if (s < 60) return s + " s";
  const two = (n) => String(n).padStart(2, "0");
  const h = Math.floor(s / 3600), m = Math.floor((s % 3600) / 60);
  return h > 0 ? h + ":" + two(m) + ":" + two(s % 60) : m + ":" + two(s % 60);
}

// Writes `text` only when it differs: every write costs the browser a layout and a frame.
function setText(element, text) {
  if (element.textContent !== text) element.textContent = text;
}

// `fn` at most every `interval` ms: a call within the interval runs once when it ends, with the
// newest arguments (messages arrive several times a second; a person reads a line or a chart
// about once, and each drawing costs the browser far more than receiving the message).
function throttled(fn, interval) {
  let last = -Infinity, pending = null;
  const run = () => {
    last = performance.now();
    const args = pending;
    pending = null;
    fn(...args);
  };
  const call = (...args) => {
    const due = last + interval - performance.now();
    const scheduled = pending !== null;
    pending = args;
    if (due <= 0 && !scheduled) run();
    else if (!scheduled) setTimeout(run, due);
  };
  return call;
}

// Text that changes with each message (the fleet's rows, a job's progress line): at most every
// kLineInterval ms, so a message reaches the page within it (docs/dashboard.md).
const kLineInterval = 500;

function numberText(v) { return v === null || v === undefined ? "-" : Number(v).toPrecision(5); }
function nowMs() { return performance.timeOrigin + performance.now(); }

// When the page first showed a progress message: the element's data attributes, and the delay
// from the message's timestamp (server clock) in window.cycloptShownLatencyMs (docs/dashboard.md:
// how the browser test measures it; the last 1000).
window.cycloptShownLatencyMs = [];
// Only messages that arrive while the page is open count: the first rows of a page show messages
// sent before it was opened.
function noteShown(element, progressUs) {
  if (!progressUs || element.dataset.progressUs === String(progressUs)) return;
  const update = element.dataset.progressUs !== undefined;
  element.dataset.progressUs = progressUs;
  element.dataset.shownMs = nowMs();
  if (!update) return;
  window.cycloptShownLatencyMs.push(nowMs() - progressUs / 1000);
  if (window.cycloptShownLatencyMs.length > 1000) window.cycloptShownLatencyMs.shift();
}

// An event stream whose connection state shows in the header. Each stream starts with the full
// state, and `onOpen` runs before its first event (also after a reconnect), so a view restarts
// from it. A hidden tab closes its stream and opens it again when shown: a browser keeps at most
// six HTTP/1.1 connections to one server, and every open stream holds one.
function stream(url, handlers, onOpen) {
  const state = document.getElementById("connection");
  let source = null;
  const connect = () => {
    const opened = new EventSource(url);
    source = opened;
    source.onopen = () => {
      state.textContent = "live";
      if (onOpen) onOpen();
    };
    // A refused stream (no such job, not this key's, not logged in) is not retried by the browser.
    source.onerror = () => {
      state.textContent = opened.readyState === EventSource.CLOSED ? "refused: no such job, or not yours to read (reload to retry)"
                                                                   : "reconnecting ...";
    };
    for (const [name, handler] of Object.entries(handlers))
      source.addEventListener(name, (e) => handler(JSON.parse(e.data)));
  };
  document.addEventListener("visibilitychange", () => {
    if (document.hidden && source) {
      source.close();
      source = null;
      state.textContent = "paused while the tab is hidden";
    } else if (!document.hidden && !source) {
      connect();
    }
  });
  connect();
}

// --- Fleet ---------------------------------------------------------------------------------------

const fleetColumns = [
  { key: "id", title: "ID", number: true, text: (r) => r.id },
  { key: "name", title: "Name", cls: "name", text: (r) => r.name || "-" },
  { key: "kind", title: "Kind", text: (r) => r.kind },
  { key: "foot", title: "Foot", text: (r) => r.foot || "-" },
  { key: "state", title: "State", cls: "state", text: (r) => r.state },
  { key: "percent", title: "Progress", cell: progressCell },
  { key: "phase", title: "Phase", cls: "phase", text: (r) => r.phase || "-" },
  { key: "eta_seconds", title: "ETA", number: true, text: (r) => (r.state === "running" ? durationText(r.eta_seconds) : "-") },
  { key: "best_objective", title: "Best", number: true, text: (r) => numberText(r.best_objective) },
  { key: "run_seconds", title: "Run", number: true, text: (r) => (r.state === "queued" ? "-" : durationText(r.run_seconds)) },
  { key: "submitted", title: "Submitted", text: (r) => r.submitted || "-" },
  { key: "started", title: "Started", text: (r) => r.started || "-" },
  { key: "why", title: "Outcome / why", cls: "why", text: whyText },
];

function progressCell(td, r) {
  if (r.state === "queued") { td.textContent = "-"; return; }
  const bar = el("span", { class: "bar" });
  const fill = el("span");
  fill.style.width = Math.max(0, Math.min(100, r.percent || 0)) + "%";
  bar.appendChild(fill);
  td.appendChild(bar);
  td.appendChild(document.createTextNode(percentText(r.percent, r.percent_lower_bound)));
}

function whyText(r) {
  const parts = [];
  if (r.state === "queued") parts.push("queue position " + r.queue_position);
  if (r.cancel_requested && (r.state === "queued" || r.state === "running")) parts.push("cancel requested");
  if (r.error) parts.push(r.error);
  if (r.state === "done" && !r.error) parts.push("converged");
  return parts.join("; ") || "-";
}

function fleetView(main) {
  const params = new URLSearchParams(location.search);
  const view = { state: params.get("state") || "", kind: params.get("kind") || "",
                 sort: params.get("sort") || "id", ascending: params.get("order") === "ascending" };
  const rows = new Map();   // id -> row
  const lines = new Map();  // id -> <tr>
  main.appendChild(el("h1", {}, "Jobs"));
  const controls = el("div", { class: "controls" });
  const stateSelect = el("select", { id: "state-filter" });
  for (const s of ["", "queued", "running", "done", "incomplete", "failed", "cancelled"])
    stateSelect.appendChild(el("option", { value: s }, s || "every state"));
  stateSelect.value = view.state;
  const kindSelect = el("select", { id: "kind-filter" });
  const count = el("span", { id: "job-count" });
  const stateLabel = el("label", {}, "State ");
  stateLabel.appendChild(stateSelect);
  const kindLabel = el("label", {}, "Kind ");
  kindLabel.appendChild(kindSelect);
  controls.append(stateLabel, kindLabel, count);
  main.appendChild(controls);
  const table = el("table", { id: "fleet" });
  const headRow = el("tr");
  for (const c of fleetColumns) {
    const th = el("th", { "data-key": c.key }, c.title);
    th.addEventListener("click", () => {
      view.ascending = view.sort === c.key ? !view.ascending : c.key !== "id";
      view.sort = c.key;
      remember();
      render();
    });
    headRow.appendChild(th);
  }
  table.appendChild(el("thead")).appendChild(headRow);
  const body = table.appendChild(el("tbody"));
  main.appendChild(table);
  stateSelect.addEventListener("change", () => { view.state = stateSelect.value; remember(); render(); });
  kindSelect.addEventListener("change", () => { view.kind = kindSelect.value; remember(); render(); });

  // The filter and sort in the URL: a reload or the back button shows the same view.
  function remember() {
    const q = new URLSearchParams();
    if (view.state) q.set("state", view.state);
    if (view.kind) q.set("kind", view.kind);
    if (view.sort !== "id") q.set("sort", view.sort);
    if (view.ascending) q.set("order", "ascending");
    history.replaceState(null, "", location.pathname + (q.toString() ? "?" + q : ""));
  }

  function fill(tr, r) {
    tr.replaceChildren();
    tr.className = r.state;
    for (const c of fleetColumns) {
      const td = el("td", { class: (c.cls || "") + (c.number ? " number" : "") });
      if (c.cell) c.cell(td, r);
      else if (c.key === "id") td.appendChild(el("a", { href: "/job/" + r.id }, r.id));
      else if (c.key === "name") td.appendChild(el("a", { href: "/job/" + r.id, title: r.name }, c.text(r)));
      else td.textContent = c.text(r);
      if (c.cls === "phase" || c.cls === "why") td.title = td.textContent;  // cut to the column; whole on hover
      tr.appendChild(td);
    }
    noteShown(tr, r.progress_us);
  }

  function sortValue(r) {
    const v = view.sort === "why" ? whyText(r) : r[view.sort];
    return v === null || v === undefined ? -Infinity : v;
  }

  function render() {
    const kinds = [...new Set([...rows.values()].map((r) => r.kind))].sort();
    if (kindSelect.options.length !== kinds.length + 1) {
      kindSelect.replaceChildren(el("option", { value: "" }, "every kind"));
      for (const k of kinds) kindSelect.appendChild(el("option", { value: k }, k));
      kindSelect.value = view.kind;
    }
    const shown = [...rows.values()]
      .filter((r) => (!view.state || r.state === view.state) && (!view.kind || r.kind === view.kind))
      .sort((a, b) => {
        const x = sortValue(a), y = sortValue(b);
        const order = x < y ? -1 : x > y ? 1 : a.id - b.id;
        return view.ascending ? order : -order;
      });
    body.replaceChildren(...shown.map((r) => lines.get(r.id)));
    count.textContent = shown.length + " of " + rows.size + " jobs";
    for (const th of headRow.children) {
      th.classList.toggle("sorted", th.dataset.key === view.sort);
      th.classList.toggle("ascending", view.ascending);
    }
  }

  // Rows changed since the table was last drawn; drawn at most every kLineInterval ms.
  const changedRows = new Map();
  const drawChanged = throttled(() => {
    for (const r of changedRows.values()) {
      if (!lines.has(r.id)) lines.set(r.id, el("tr", { "data-id": r.id }));
      fill(lines.get(r.id), r);
    }
    changedRows.clear();
    render();
    if (!main.dataset.firstRowsMs) main.dataset.firstRowsMs = performance.now();
  }, kLineInterval);
  stream("/api/fleet/events", {
    rows: (changed) => {
      for (const r of changed) {
        rows.set(r.id, r);
        changedRows.set(r.id, r);
      }
      drawChanged();
    },
  });
}

// --- Job -----------------------------------------------------------------------------------------

// A uPlot chart that is rebuilt when its series change and fed new data otherwise. `show` keeps
// the newest data; the page's drawing (jobView's `redraw`) calls `flush`, which draws it when the
// chart was last drawn kChartInterval ms ago or more: a chart costs the browser more than the text.
const kChartInterval = 1000;
class Chart {
  constructor(container, options) {
    this.container = container;
    this.options = options;  // title, x label, y label, log y
    this.plot = null;
    this.labels = "";
    this.drawn = -Infinity;
    this.pending = null;
  }
  show(labels, data) { this.pending = { labels, data }; }
  // True while data waits for its turn.
  flush() {
    if (!this.pending) return false;
    if (performance.now() - this.drawn < kChartInterval) return true;
    this.drawn = performance.now();
    const { labels, data } = this.pending;
    this.pending = null;
    this.draw(labels, data);
    return false;
  }
  draw(labels, data) {
    const key = labels.join("\n");
    if (this.plot && key === this.labels) { this.plot.setData(data); return; }
    if (this.plot) this.plot.destroy();
    this.labels = key;
    const colors = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"];
    const series = [{ label: this.options.x }];
    labels.forEach((label, i) => {
      const envelope = label === "best envelope";
      series.push({ label, stroke: envelope ? "#000" : colors[i % colors.length], width: envelope ? 2 : 1.5,
                    dash: envelope ? [6, 4] : undefined, spanGaps: true, points: { show: true, size: 5 } });
    });
    this.plot = new uPlot({
      title: this.options.title, width: Math.max(420, this.container.clientWidth - 10), height: 320,
      scales: { x: { time: false }, y: this.options.log ? { distr: 3 } : {} },
      axes: [{ label: this.options.x },
             { label: this.options.y, size: 70,
               values: this.options.log ? (u, splits) => splits.map((v) => (v === null ? "" : v.toExponential(0))) : undefined }],
      series,
    }, data, this.container);
  }
}

// The result curve: the converged points' objective over each curve's parameter, one series per
// curve, and with `envelope` (a foot comparison: a curve per foot) their lower envelope, the best
// foot at each speed.
function resultData(curves, points, envelope) {
  const ids = [...new Set(points.map((p) => p.curve))].sort((a, b) => a - b);
  const xs = [...new Set(points.filter((p) => p.parameter !== null).map((p) => p.parameter))].sort((a, b) => a - b);
  const column = new Map(xs.map((x, i) => [x, i]));
  const data = [xs];
  const labels = [];
  for (const id of ids) {
    const y = new Array(xs.length).fill(null);
    for (const p of points)
      if (p.curve === id && p.parameter !== null && p.objective !== null && p.converged)
        y[column.get(p.parameter)] = p.objective;
    data.push(y);
    const c = curves.get(id);
    labels.push(c && c.name ? c.name : "curve " + id);
  }
  if (envelope && ids.length > 1) {
    labels.push("best envelope");
    data.push(xs.map((_, i) => {
      const ys = data.slice(1).map((y) => y[i]).filter((v) => v !== null);
      return ys.length ? Math.min(...ys) : null;
    }));
  }
  return { labels, data };
}

function progressText(p) {
  let line = percentText(p.percent, p.percent_lower_bound);
  if (p.points_total > 0) line += " " + p.points_done + "/" + p.points_total;
  line += " | " + durationText(p.elapsed_seconds) + ", ETA " + durationText(p.eta_seconds);
  if (p.phase) line += " | " + p.phase + (p.phase_total > 0 ? " " + p.phase_done + "/" + p.phase_total : "");
  if (p.best_objective !== null) line += " | best " + numberText(p.best_objective);
  return line;
}

function jobView(main, id) {
  const title = el("h1", { id: "job-title" }, "Job " + id);
  const summary = el("div", { id: "job-summary" });
  const line = el("div", { class: "progress-line", id: "progress-line" }, "waiting for the job's progress ...");
  const actions = el("div", { class: "controls" });
  const cancel = el("button", { id: "cancel", type: "button" }, "Cancel job");
  const answer = el("span", { id: "cancel-answer" });
  actions.append(cancel, el("a", { href: "/job/" + id + "/export.json", id: "export" }, "export (JSON)"),
                 el("a", { href: "/job/" + id + "/report", id: "report-link" }, "report"), answer);
  const charts = el("div", { class: "charts" });
  const resultBox = el("div", { class: "chart", id: "result-chart", "data-points": "0" });
  const convergenceBox = el("div", { class: "chart", id: "convergence-chart" });
  charts.append(resultBox, convergenceBox);
  const convergenceNote = el("div", { class: "note" },
    "Convergence of the solve in progress: objective and constraint violation as the progress messages " +
    "report them (a few per second, not every iteration); the messages carry no stationarity error.");
  const events = el("table", { id: "events" });
  const report = el("div", { id: "report" });
  main.append(title, summary, line, actions, el("h2", {}, "Result"), charts, convergenceNote,
              el("h2", {}, "Events"), events, report);

  const curves = new Map();
  const points = [];
  const resultChart = new Chart(resultBox, { title: "objective over the curve's parameter", x: "parameter", y: "objective" });
  const convergenceChart = new Chart(convergenceBox, { title: "solve in progress", x: "iteration", y: "log scale", log: true });
  const samples = { key: "", iteration: [], objective: [], violation: [] };
  let finalState = false;
  let kind = "";

  cancel.addEventListener("click", async () => {
    cancel.disabled = true;
    answer.textContent = "cancelling ...";
    try {
      const response = await fetch("/api/job/" + id + "/cancel", { method: "POST", headers: { "X-Cyclopt-Action": "cancel" } });
      const reply = response.headers.get("Content-Type").startsWith("application/json") ? await response.json()
                                                                                         : { ok: false, message: response.statusText };
      answer.textContent = reply.message;
    } catch (e) {
      answer.textContent = "cancel failed: " + e;
    }
    cancel.disabled = false;
  });

  // What changed since the page was last drawn; drawn together, at most every kLineInterval ms,
  // so that a message reaches the page within that (docs/dashboard.md states the latency) and the
  // browser draws one frame for all of it.
  const changes = { result: false, progress: null, running: false };
  const redraw = throttled(() => {
    if (changes.result) {
      changes.result = false;
      const { labels, data } = resultData(curves, points, kind === "foot_comparison");
      const c = [...curves.values()][0];
      resultChart.options.x = c && c.parameter_name ? c.parameter_name : "parameter";
      if (data[0].length > 0) resultChart.show(labels, data);
      if (resultBox.dataset.points !== String(points.length)) resultBox.dataset.points = points.length;
    }
    if (changes.progress && changes.running) {
      setText(line, progressText(changes.progress));
      noteShown(line, changes.progress.timestamp_us);
    }
    changes.progress = null;
    const waiting = [resultChart.flush(), convergenceChart.flush()].some((w) => w);
    if (waiting) redraw();
  }, kLineInterval);
  const drawResult = () => { changes.result = true; redraw(); };

  const restart = () => {
    curves.clear();
    points.length = 0;
    events.replaceChildren();
    samples.key = "";
  };
  stream("/api/job/" + id + "/events", {
    job: (row) => {
      if (!row) { setText(summary, "not in the database (yet)"); return; }
      setText(title, "Job " + row.id + ": " + (row.name || row.kind));
      kind = row.kind;
      if (document.title !== "cyclopt job " + row.id) document.title = "cyclopt job " + row.id;
      setText(summary, [row.kind, row.foot ? "foot " + row.foot : "", row.state,
                        row.submitted ? "submitted " + row.submitted : "", row.started ? "started " + row.started : "",
                        row.finished ? "ended " + row.finished : "", row.error].filter((s) => s).join(" · "));
      if (summary.dataset.state !== row.state) summary.dataset.state = row.state;
      const active = row.state === "queued" || row.state === "running";
      if (cancel.hidden === active) cancel.hidden = !active;
      changes.running = row.state === "running";  // else the row's line is the last word
      if (row.state === "queued") setText(line, "queued, position " + row.queue_position);
      else if (!active) setText(line, percentText(row.percent, row.percent_lower_bound) + " | " + row.state +
                                      " after " + durationText(row.run_seconds) +
                                      (row.best_objective !== null ? " | best " + numberText(row.best_objective) : ""));
      if (!active && !finalState) {
        finalState = true;
        report.replaceChildren(el("h2", {}, "Report"), el("iframe", { class: "report", src: "/job/" + id + "/report", title: "report" }));
      }
    },
    progress: (p) => {
      changes.progress = p;
      const key = p.curve + "|" + p.parameter;
      if (key !== samples.key || (samples.iteration.length && p.iteration < samples.iteration[samples.iteration.length - 1])) {
        Object.assign(samples, { key, iteration: [], objective: [], violation: [] });
      }
      if (p.iteration >= 0 && (samples.iteration.length === 0 || p.iteration > samples.iteration[samples.iteration.length - 1])) {
        const positive = (v) => (v !== null && v > 0 ? v : null);
        samples.iteration.push(p.iteration);
        samples.objective.push(positive(p.objective));
        samples.violation.push(positive(p.constraint_violation));
        convergenceChart.options.title = "solve in progress: " + (p.phase || "") ;
        convergenceChart.show(["objective", "constraint violation"], [samples.iteration, samples.objective, samples.violation]);
      }
      redraw();
    },
    curves: (rows) => { for (const c of rows) curves.set(c.curve, c); drawResult(); },
    points: (rows) => { points.push(...rows); drawResult(); },
    events: (rows) => {
      for (const e of rows) {
        const tr = el("tr");
        tr.append(el("td", {}, e.at), el("td", {}, e.kind), el("td", {}, e.message));
        events.appendChild(tr);
      }
    },
  }, restart);
}

// --- route ---------------------------------------------------------------------------------------

(function route() {
  const main = document.getElementById("main");
  const job = location.pathname.match(/^\/job\/(\d+)$/);
  if (job) jobView(main, job[1]);
  else fleetView(main);
})();
