// The lab's page: polls the server's state, shows the chapters, a chapter's
// bench and a pixel's two ray trees. Text from the server is always set as
// text, never as HTML.
"use strict";

const WIDTH = 160, HEIGHT = 120;
// An address ending in #07-termination/accuracy opens chapter 7 scrolled to its accuracy page.
const lab = { scrollToAccuracy: location.hash.endsWith("/accuracy"), version: -1, chapter: null, chosen: false, pixel: null, state: null, benchKey: null, lastShown: undefined };

function el(tag, attrs, ...children) {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attrs || {})) {
    if (key === "class") node.className = value;
    else if (key.startsWith("on")) node.addEventListener(key.slice(2), value);
    else node.setAttribute(key, value);
  }
  for (const child of children) {
    if (child === null || child === undefined) continue;
    node.append(child instanceof Node ? child : String(child));
  }
  return node;
}

async function getJson(path) {
  const response = await fetch(path, { cache: "no-store" });
  const body = await response.json().catch(() => ({ error: `the lab answered ${response.status}` }));
  if (!response.ok && !body.error) body.error = `the lab answered ${response.status}`;
  return body;
}

// ---- chapters and progress ----

function showChapters(rows) {
  const body = document.querySelector("#table tbody");
  body.replaceChildren();
  for (const row of rows) {
    const tr = el("tr", { "data-folder": row.folder, onclick: () => choose(row.folder, true) },
      el("td", {}, row.folder),
      el("td", {}, row.passed ?? (row.run === false ? "-" : "…")),
      el("td", {}, row.failed ?? (row.run === false ? "-" : "…")),
      el("td", {}, row.exercises ?? ""));
    if (row.here) tr.classList.add("here");
    if (row.passes) tr.classList.add("passes");
    if (row.folder === lab.chapter) tr.classList.add("selected");
    body.append(tr);
    if (row.run && !row.passes && row.failure) {
      body.append(el("tr", { onclick: () => choose(row.folder, true) }, el("td", { colspan: 4, class: "failure" }, row.failure)));
    }
  }
  showExercises(rows.find((r) => r.folder === lab.chapter));
}

// The selected chapter's exercises, each with its three hints.
function showExercises(row) {
  const box = document.getElementById("exercises");
  box.replaceChildren();
  if (!row || !row.exercise_list) return;
  box.append(el("h3", {}, `Exercises of ${row.folder}`));
  if (row.next) box.append(el("p", { class: "next" }, `next: ${row.next.id} in ${row.next.file}:${row.next.line}: ${row.next.hint}`));
  const list = el("ul", {});
  for (const exercise of row.exercise_list) {
    const item = el("li", {}, el("span", { class: exercise.open ? "open" : "written", title: exercise.open ? "not written yet: its todo! is still there" : "written: the chapter's tests say whether it is right" }, exercise.open ? "○ " : "✎ "), exercise.id, " ");
    for (const level of [1, 2, 3]) item.append(el("button", { onclick: () => hint(exercise.id, level), title: ["", "a nudge: what to compute", "the text that derives it", "the tests that check it (runs them)"][level] }, `hint ${level}`));
    // The answer, only once `workbook hint` offers it: after an attempt that compiles.
    if (exercise.answer) item.append(el("button", { class: "answer", onclick: () => hint(exercise.id, 4), title: "the answer, to compare with your attempt (runs the tests)" }, "answer"));
    list.append(item);
  }
  box.append(list);
}

async function hint(id, level) {
  const box = document.getElementById("hint");
  box.hidden = false;
  document.getElementById("hint-title").textContent = level === 4 ? `the answer to ${id}` : `hint ${level} of 3: ${id}`;
  const text = document.getElementById("hint-text");
  text.textContent = level >= 3 ? "running the chapter's tests…" : "…";
  const answer = await getJson(`api/hint?id=${encodeURIComponent(id)}&level=${level}`);
  text.textContent = answer.error ? `error: ${answer.error}` : answer.text;
}

// ---- a chapter's bench ----

async function choose(folder, byHand) {
  if (byHand) lab.chosen = true;
  if (lab.chapter !== folder) { lab.pixel = null; document.getElementById("pixel").hidden = true; }
  lab.chapter = folder;
  lab.benchKey = null;
  if (lab.state && lab.state.rows) showChapters(lab.state.rows);
  location.hash = folder;
  if (typeof showAccuracy === "function") showAccuracy(folder);
  const answer = await getJson(`api/bench?chapter=${encodeURIComponent(folder)}`);
  if (answer.error) message([answer.error], "error");
  refresh(true);
}

function message(lines, kind) {
  const box = document.getElementById("bench-message");
  box.replaceChildren();
  if (!lines.length) return;
  if (kind === "error") box.append(el("pre", { class: "error" }, lines.join("\n")));
  else box.append(el("div", { class: `message ${kind}` }, lines.join("\n")));
}

function showBench(state) {
  const folder = lab.chapter;
  if (!folder) return;
  document.getElementById("bench-title").textContent = `Chapter ${folder}`;
  const bench = state.benches[folder];
  const version = state.version;
  document.getElementById("reference").src = `pictures/${folder}/reference.png`;
  const yours = document.getElementById("yours"), difference = document.getElementById("difference");
  const diagnosis = document.getElementById("diagnosis");
  if (!bench) {
    message(["building and rendering your picture…"], "info");
    return;
  }
  const key = JSON.stringify(bench);
  if (lab.benchKey === key) return;
  lab.benchKey = key;
  const row = (state.rows || []).find((r) => r.folder === folder);
  const first = row && row.next ? `${row.next.id} first (${row.next.file}:${row.next.line}): ${row.next.hint}` : null;
  yours.removeAttribute("src"); difference.removeAttribute("src");
  diagnosis.hidden = true;
  if (bench.build_errors.length) {
    message(["chapter " + folder + " does not compile:", ...bench.build_errors], "error");
  } else if (bench.todo) {
    message([`Your picture cannot be drawn yet: rendering reached the todo! of exercise ${bench.todo[0]} (${bench.todo[1]}).`,
      first ? `The chapter's text asks for ${first}` : null,
      "The reference's picture is shown meanwhile."].filter(Boolean), "info");
  } else if (bench.failure) {
    message([bench.failure], "error");
  } else {
    const timing = bench.since_save != null ? ` (picture ${bench.since_save.toFixed(2)} s after your save)` : "";
    message([bench.verdict + timing], bench.passed ? "good" : "bad");
    yours.src = `pictures/${folder}/yours.png?v=${version}`;
    if (!bench.passed) difference.src = `pictures/${folder}/difference.png?v=${version}`;
    if (bench.diagnosis) { diagnosis.hidden = false; diagnosis.textContent = bench.diagnosis; }
    if (!lab.pixel && bench.regions.length) {
      const [x0, y0, x1, y1] = bench.regions[0];
      pick(Math.floor((x0 + x1) / 2), Math.floor((y0 + y1) / 2));
      return;
    }
  }
  if (lab.pixel) pick(lab.pixel[0], lab.pixel[1]);
}

// ---- pixels and their trees ----

function placeMarks() {
  for (const picture of document.querySelectorAll(".picture")) {
    const mark = picture.querySelector(".mark");
    if (!lab.pixel) { mark.style.display = "none"; continue; }
    const scale = picture.clientWidth / WIDTH;
    mark.style.display = "block";
    mark.style.left = `${lab.pixel[0] * scale}px`;
    mark.style.top = `${lab.pixel[1] * scale}px`;
    mark.style.width = mark.style.height = `${Math.max(scale, 2)}px`;
  }
}

async function pick(x, y) {
  if (!lab.chapter) return;
  x = Math.min(WIDTH - 1, Math.max(0, x)); y = Math.min(HEIGHT - 1, Math.max(0, y));
  lab.pixel = [x, y];
  placeMarks();
  const section = document.getElementById("pixel");
  section.hidden = false;
  document.getElementById("pixel-label").textContent = `(${x}, ${y}) of ${WIDTH}×${HEIGHT}`;
  const asked = `${lab.chapter}/${x},${y}`;
  lab.asked = asked;
  const url = `api/pixel?chapter=${encodeURIComponent(lab.chapter)}&x=${x}&y=${y}`;
  let answer = await getJson(url);
  // Two earlier pixels still run your code: ask again while this one is wanted.
  while (answer.busy && lab.asked === asked) {
    await new Promise((done) => setTimeout(done, 200));
    answer = await getJson(url);
  }
  if (lab.asked !== asked) return;  // a later click won
  showTrees(answer);
}

function showTrees(answer) {
  const first = document.getElementById("first-difference");
  const svg = document.getElementById("svg");
  if (answer.error) { first.textContent = `error: ${answer.error}`; return; }
  const comparison = answer.comparison || {};
  const difference = comparison.first || null;
  first.className = "";
  if (comparison.error) first.textContent = comparison.error;
  else if (difference) first.textContent = `first difference (of ${comparison.differences} in ${comparison.values} values compared), at ${difference.text}`;
  else if (answer.comparison) { first.textContent = `your tree matches the reference's (${comparison.values} values compared)`; first.className = "same"; }
  else first.textContent = "no comparison: one of the trees is missing";
  document.getElementById("shortened").textContent = answer.shortened;
  // Which pixel's trees these are (the label changes at the click already).
  document.getElementById("pixel").dataset.shown = answer.pixel.join(",");
  lab.trees = answer;
  const all = document.getElementById("all-fields").checked;
  drawTree("tree-yours", all || !answer.yours_short ? answer.yours : { tree: answer.yours_short }, difference);
  drawTree("tree-reference", answer.reference, difference);
  const drawn = (img, text) => { img.hidden = !text; if (text) img.src = "data:image/svg+xml;charset=utf-8," + encodeURIComponent(text); };
  drawn(svg, answer.svg);
  drawn(document.getElementById("svg-reference"), answer.reference_svg);
  document.getElementById("svg-box").hidden = !answer.svg && !answer.reference_svg;
}

function drawTree(id, side, difference) {
  const box = document.getElementById(id);
  box.replaceChildren();
  if (side.error) { box.append(el("pre", { class: "error" }, side.error)); return; }
  box.append(drawRay(side.tree.primary, ["primary"], difference));
}

function number(value) {
  return typeof value === "number" ? String(Number(value.toPrecision(6))) : JSON.stringify(value);
}

function show(value) {
  if (Array.isArray(value) && value.every((v) => typeof v === "number")) return "(" + value.map(number).join(", ") + ")";
  if (value && typeof value === "object") return JSON.stringify(value);
  return number(value);
}

// The fields of a ray as verify names them: `t` of its hit is `hit.t`, the
// status of light 1 is `lights[1].status`.
function fields(ray) {
  const out = [];
  const add = (prefix, node) => {
    for (const [key, value] of Object.entries(node)) {
      if (key === "secondary") continue;
      if (key === "lights" && Array.isArray(value)) {
        for (const light of value) add(`lights[${light.light}].`, light);
      } else if (value && typeof value === "object" && !Array.isArray(value)) add(`${prefix}${key}.`, value);
      else out.push([prefix + key, value]);
    }
  };
  add("", ray);
  return out;
}

function swatch(color) {
  const span = el("span", { class: "swatch", title: "the colour it brings back" });
  const c = (v) => Math.round(255 * Math.min(1, Math.max(0, v)));
  span.style.background = `rgb(${c(color[0])}, ${c(color[1])}, ${c(color[2])})`;
  return span;
}

function drawRay(ray, path, difference) {
  const here = difference && difference.rays.join("/") === path.join("/");
  const hit = ray.hit ? `hits object ${ray.hit.object} at t = ${number(ray.hit.t)}` : "hits nothing";
  const weights = ray.path_weight || ray.weight || [1, 1, 1];
  const folded = (ray.depth || 0) > 3 || weights.every((w) => w < 0.01);
  const details = el("details", { class: "ray" + (here && !difference.field ? " differs" : "") });
  if (!folded) details.open = true;
  details.append(el("summary", {}, `${ray.kind} (depth ${ray.depth ?? path.length - 1}): ${hit}`, Array.isArray(ray.color) ? swatch(ray.color) : null));
  const table = el("table", { class: "fields" });
  for (const [name, value] of fields(ray)) {
    const tr = el("tr", {}, el("td", {}, name), el("td", {}, show(value)));
    if (here && difference.field === name) tr.classList.add("differs");
    table.append(tr);
  }
  details.append(table);
  for (const child of ray.secondary || []) details.append(drawRay(child, [...path, child.kind], difference));
  return details;
}

// ---- clicks and keys ----

for (const picture of document.querySelectorAll(".picture")) {
  picture.addEventListener("click", (event) => {
    const box = picture.getBoundingClientRect();
    const scale = box.width / WIDTH;
    pick(Math.floor((event.clientX - box.left) / scale), Math.floor((event.clientY - box.top) / scale));
  });
}

document.addEventListener("keydown", (event) => {
  if (!lab.pixel || event.target.closest("input, textarea")) return;
  const step = event.shiftKey ? 10 : 1;
  const moves = { ArrowLeft: [-step, 0], ArrowRight: [step, 0], ArrowUp: [0, -step], ArrowDown: [0, step] };
  const move = moves[event.key];
  if (!move) return;
  event.preventDefault();
  pick(lab.pixel[0] + move[0], lab.pixel[1] + move[1]);
});
window.addEventListener("resize", placeMarks);
document.getElementById("all-fields").addEventListener("change", () => { if (lab.trees) showTrees(lab.trees); });

// ---- polling ----

async function refresh(force) {
  const state = await getJson("api/state").catch(() => null);
  if (!state || state.error) return;
  const busy = document.getElementById("busy");
  busy.hidden = !state.busy.length;
  busy.textContent = state.busy.join(" · ");
  if (!force && state.version === lab.version) return;
  lab.version = state.version;
  lab.state = state;
  if (state.rows) showChapters(state.rows);
  document.getElementById("advice").textContent = state.progress_error ? `progress: ${state.progress_error}` : (state.advice || "testing the chapters…");
  if (!lab.chosen && state.rows) {
    const here = state.rows.find((r) => r.here && r.bench) || state.rows.filter((r) => r.bench).pop();
    if (here && here.folder !== lab.chapter) { lab.chosen = true; choose(here.folder, false); return; }
  }
  // A save in another chapter: the server renders that one; follow it.
  if (lab.lastShown === undefined) lab.lastShown = state.shown;
  if (state.shown && state.shown !== lab.lastShown) {
    lab.lastShown = state.shown;
    if (state.shown !== lab.chapter) { choose(state.shown, false); return; }
  }
  showBench(state);
}

async function start() {
  const chapters = await getJson("api/chapters");
  if (Array.isArray(chapters)) showChapters(chapters.map((c) => ({ folder: c.folder })));
  const wanted = decodeURIComponent(location.hash.slice(1)).split("/")[0];
  if (wanted && Array.isArray(chapters) && chapters.some((c) => c.folder === wanted)) await choose(wanted, true);
  await refresh(true);
  setInterval(refresh, 700);
}

start();
