// Chapter 7's accuracy page: the student's own chapter-7 binary renders a
// setting (in the background: the page polls), and each render becomes a
// point on two log-log plots, error against rays and against time, beside
// the study's curves read from its accuracy.csv. Text from the server is
// set as text, never as HTML.
"use strict";

const accuracy = { study: null, snapshot: null, polling: null, shownPoints: -1 };
const SVG = "http://www.w3.org/2000/svg";

function svgEl(tag, attrs, text) {
  const node = document.createElementNS(SVG, tag);
  for (const [key, value] of Object.entries(attrs || {})) node.setAttribute(key, value);
  if (text !== undefined) node.textContent = text;
  return node;
}

// Shown with chapter 7's bench only.
function showAccuracy(folder) {
  const section = document.getElementById("accuracy");
  section.hidden = folder !== "07-termination";
  if (section.hidden) return;
  if (!accuracy.study) {
    accuracy.study = "asked";
    getJson("api/accuracy/study").then((study) => { accuracy.study = study; drawPlots(); });
  }
  pollAccuracy();
  if (lab.scrollToAccuracy) { lab.scrollToAccuracy = false; section.scrollIntoView(); }
}

function accuracyQuery() {
  const form = document.getElementById("accuracy-form");
  const data = new FormData(form);
  return new URLSearchParams([...data.entries()].map(([k, v]) => [k, String(v)])).toString();
}

async function renderSetting(event) {
  event.preventDefault();
  const answer = await getJson(`api/accuracy/run?${accuracyQuery()}`);
  const status = document.getElementById("accuracy-status");
  if (answer.error) { status.className = "message bad"; status.textContent = answer.error; return; }
  status.className = "message info";
  status.textContent = `rendering ${answer.asked}…`;
  pollAccuracy();
}

// Polls while a render runs; stops when it is done.
async function pollAccuracy() {
  const snapshot = await getJson("api/accuracy").catch(() => null);
  if (!snapshot || snapshot.error) return;
  accuracy.snapshot = snapshot;
  const status = document.getElementById("accuracy-status");
  const button = document.getElementById("accuracy-render");
  button.disabled = !!snapshot.running;
  if (snapshot.running) {
    status.className = "message info busy-line";
    const doing = snapshot.running.phase === "building"
      ? "cargo builds your chapter 7 (a file under chapters/ changed), then it renders"
      : "your chapter-7 binary renders";
    status.textContent = `${doing} ${snapshot.running.name}… ${snapshot.running.seconds.toFixed(1)} s`;
    clearTimeout(accuracy.polling);
    accuracy.polling = setTimeout(pollAccuracy, 250);
  } else if (snapshot.error) {
    status.className = "message bad";
    status.textContent = snapshot.error;
  } else if (snapshot.points.length) {
    const p = snapshot.points[snapshot.points.length - 1];
    status.className = "message good";
    status.textContent = `${p.name}: RMSE ${p.rmse.toPrecision(4)}, ${p.rays.toLocaleString("en")} rays, ` +
      `${p.seconds.toFixed(3)} s to render (${p.wall_seconds.toFixed(2)} s from the click to the point)`;
  }
  if (snapshot.points.length !== accuracy.shownPoints) {
    accuracy.shownPoints = snapshot.points.length;
    showPoints(snapshot.points);
    if (snapshot.picture) document.getElementById("accuracy-picture").src = `api/accuracy/picture.png?n=${snapshot.points.length}`;
    drawPlots();
  }
}

function showPoints(points) {
  const body = document.querySelector("#accuracy-points tbody");
  body.replaceChildren();
  for (const p of [...points].reverse()) {
    body.append(el("tr", {}, el("td", {}, p.name), el("td", {}, p.rmse.toPrecision(4)),
      el("td", {}, p.rays.toLocaleString("en")), el("td", {}, p.seconds.toFixed(3))));
  }
}

// The study's grid rows as curves: one per (depth, threshold), through its
// jittered samplings in order of rays; the centre ray as a lone marker.
function studyCurves() {
  const rows = (accuracy.study && accuracy.study.rows) || [];
  const curves = new Map();
  for (const row of rows.filter((r) => r.group === "grid")) {
    const key = `depth ${row.max_depth}, threshold ${row.min_weight}`;
    if (!curves.has(key)) curves.set(key, { key, depth: row.max_depth, weight: row.min_weight, jittered: [], centre: null });
    const curve = curves.get(key);
    if (row.sampling === "centre") curve.centre = row; else curve.jittered.push(row);
  }
  for (const curve of curves.values()) curve.jittered.sort((a, b) => a.rays - b.rays);
  return [...curves.values()];
}

function drawPlots() {
  const points = (accuracy.snapshot && accuracy.snapshot.points) || [];
  const curves = studyCurves();
  const form = new FormData(document.getElementById("accuracy-form"));
  const depth = Number(form.get("max_depth")), weight = Number(form.get("min_weight"));
  const chosen = curves.find((c) => c.depth === depth && c.weight === weight);
  document.getElementById("accuracy-legend").textContent = accuracy.study && accuracy.study.error
    ? `the study's curves are missing: ${accuracy.study.error}`
    : `grey: the study's ${curves.length} settings (1, 4, 16 jittered rays; ○ the centre ray), from ${accuracy.study && accuracy.study.file || "accuracy.csv"}, ` +
      `measured with the complete tracer (a BVH; chapter 7's tests every object, so its times lie to the right); ` +
      (chosen ? `blue: ${chosen.key}, your setting's; ` : "") + "red: your renders (the last one ringed).";
  plot("accuracy-rays", "rays traced", (r) => r.rays, (p) => p.rays, curves, chosen, points);
  plot("accuracy-time", "seconds to render", (r) => r.seconds_median, (p) => p.seconds, curves, chosen, points);
}

// Ticks at 1, 2 and 5 times the powers of ten between 10^lo and 10^hi.
function ticks(lo, hi) {
  const out = [];
  for (let e = Math.floor(lo); e <= Math.ceil(hi); e++) {
    for (const m of [1, 2, 5]) {
      const v = m * 10 ** e;
      if (Math.log10(v) >= lo && Math.log10(v) <= hi) out.push(v);
    }
  }
  return out;
}

function tickText(v) {
  return v >= 1e4 || v < 1e-3 ? v.toExponential(0).replace("e+", "e") : String(Number(v.toPrecision(1)));
}

// A log-log plot of RMSE against `x` into the <svg> `id`.
function plot(id, xLabel, studyX, pointX, curves, chosen, points) {
  const svg = document.getElementById(id);
  svg.replaceChildren();
  const W = 420, H = 300, left = 58, right = 12, top = 12, bottom = 40;
  const all = [];
  for (const c of curves) for (const r of [...c.jittered, c.centre].filter(Boolean)) all.push([studyX(r), r.rmse]);
  for (const p of points) all.push([pointX(p), p.rmse]);
  const valid = all.filter(([x, y]) => x > 0 && y > 0);
  if (!valid.length) { svg.append(svgEl("text", { x: 20, y: 40 }, "no study and no point yet")); return; }
  // The range of the values, a little wider, in decades (log10).
  const range = (values) => [Math.log10(Math.min(...values)) - 0.1, Math.log10(Math.max(...values)) + 0.1];
  const [x0, x1] = range(valid.map((v) => v[0]));
  const [y0, y1] = range(valid.map((v) => v[1]));
  const lx = (x) => left + (W - left - right) * (Math.log10(x) - x0) / (x1 - x0);
  const ly = (y) => H - bottom - (H - top - bottom) * (Math.log10(y) - y0) / (y1 - y0);
  const grid = svgEl("g", { class: "axes" });
  for (const v of ticks(x0, x1)) {
    grid.append(svgEl("line", { x1: lx(v), x2: lx(v), y1: top, y2: H - bottom }));
    grid.append(svgEl("text", { x: lx(v), y: H - bottom + 14, "text-anchor": "middle" }, tickText(v)));
  }
  for (const v of ticks(y0, y1)) {
    grid.append(svgEl("line", { x1: left, x2: W - right, y1: ly(v), y2: ly(v) }));
    grid.append(svgEl("text", { x: left - 4, y: ly(v) + 4, "text-anchor": "end" }, tickText(v)));
  }
  grid.append(svgEl("text", { x: (left + W - right) / 2, y: H - 6, "text-anchor": "middle" }, xLabel));
  grid.append(svgEl("text", { x: 12, y: (top + H - bottom) / 2, "text-anchor": "middle", transform: `rotate(-90 12 ${(top + H - bottom) / 2})` }, "RMSE (linear)"));
  svg.append(grid);
  const line = (rows, cls) => svgEl("polyline", { class: cls, points: rows.map((r) => `${lx(studyX(r))},${ly(r.rmse)}`).join(" ") });
  for (const c of curves.filter((c) => c !== chosen)) {
    svg.append(line(c.jittered, "study"));
    if (c.centre) svg.append(svgEl("circle", { class: "study centre", cx: lx(studyX(c.centre)), cy: ly(c.centre.rmse), r: 3 }));
  }
  if (chosen) {
    svg.append(line(chosen.jittered, "study chosen"));
    if (chosen.centre) svg.append(svgEl("circle", { class: "study chosen centre", cx: lx(studyX(chosen.centre)), cy: ly(chosen.centre.rmse), r: 4 }));
  }
  points.forEach((p, i) => {
    const [cx, cy] = [lx(pointX(p)), ly(p.rmse)];
    const dot = svgEl("circle", { class: "yours" + (i === points.length - 1 ? " last" : ""), cx, cy, r: i === points.length - 1 ? 6 : 4 });
    dot.append(svgEl("title", {}, `${p.name}: RMSE ${p.rmse.toPrecision(4)}`));
    svg.append(dot);
  });
}

document.getElementById("accuracy-form").addEventListener("submit", renderSetting);
// The centre ray has no seed: its input is off while "centre" is picked.
function seedOnlyWhenJittered() {
  const form = document.getElementById("accuracy-form");
  form.elements.seed.disabled = form.elements.rays.value === "centre";
}
document.getElementById("accuracy-form").addEventListener("change", () => { seedOnlyWhenJittered(); drawPlots(); });
seedOnlyWhenJittered();
if (lab.chapter) showAccuracy(lab.chapter);
