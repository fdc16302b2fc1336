// The page: picks or takes a scene, builds a `prime` command line from the
// controls, runs it in the worker (worker.js) and shows what its window draws
// in the canvas. Everything the renderers do is the C++ program's; this file
// only moves files, events and pixels between the browser and it.
"use strict";

const $ = (id) => document.getElementById(id);
const canvas = $("canvas");
const context = canvas.getContext("2d");

// The events ring shared with the program (web_window_module.cpp has the
// layout): [0] written, [1] read, then 256 slots of 16 ints.
const kSlots = 256;
const kSlotInts = 16;
const kEvent = {quit: 1, key: 2, redraw: 3, motion: 4, button: 5, wheel: 6};
const kNamedKeys = {Escape: 0x10001, ArrowLeft: 0x10002, ArrowRight: 0x10003, ArrowUp: 0x10004,
                    ArrowDown: 0x10005, Home: 0x10006, F11: 0x10007, F12: 0x10008, Pause: 0x10009};

let worker = null;
let ring = null;
let running = false;
let scenes = {prime: [], malone: [], cgl: []};
let dropped = null;  // {system, name, files: {path: bytes}, target}
let lastFiles = {};  // what the last render wrote, path -> bytes
let lastNames = {};  // path -> download name
let pending = null;  // the resolve of the running command's promise
let lastButtons = 0;
let lastX = 0;
let lastY = 0;

function status(text) {
  $("status").textContent = text;
}

function showError(lines) {
  const e = $("error");
  e.hidden = lines.length === 0;
  e.textContent = lines.join("\n");
}

function log(line) {
  const l = $("log");
  l.textContent += line + "\n";
  l.scrollTop = l.scrollHeight;
}

function pushEvent(values) {
  if (!ring || !running) return;
  const written = Atomics.load(ring, 0);
  if (written - Atomics.load(ring, 1) >= kSlots) return;  // full: the program is busy
  const at = 4 + (written % kSlots) * kSlotInts;
  for (let k = 0; k < kSlotInts; ++k) ring[at + k] = values[k] || 0;
  Atomics.store(ring, 0, written + 1);
}

// type, key code, shift, x, y, dx, dy, button, down, buttons, wheel, exposed
function event(type, fields) {
  const f = fields || {};
  pushEvent([type, f.code, f.shift ? 1 : 0, f.x, f.y, f.dx, f.dy, f.button, f.down ? 1 : 0,
             f.buttons, f.wheel, f.exposed ? 1 : 0]);
}

function onWindow(m) {
  switch (m.window) {
    case "open":
    case "resize":
    case "show":
      if (canvas.width !== m.a || canvas.height !== m.b) {
        canvas.width = m.a;
        canvas.height = m.b;
      }
      if (m.window === "show") {
        canvas.focus();
        event(kEvent.redraw, {exposed: true});
      }
      break;
    case "rect": {
      // XRGB8888 words (0x00RRGGBB) to the canvas's RGBA bytes.
      const image = context.createImageData(m.w, m.h);
      const rgba = new Uint32Array(image.data.buffer);
      const n = m.w * m.h;
      for (let i = 0; i < n; ++i) {
        const v = m.rows[i];
        rgba[i] = 0xff000000 | ((v & 0xff) << 16) | (v & 0xff00) | ((v >> 16) & 0xff);
      }
      context.putImageData(image, m.x, m.y);
      break;
    }
    case "title":
      status(m.text);
      break;
    case "fullscreen":
      if (m.a) canvas.requestFullscreen().catch(() => {});
      else if (document.fullscreenElement) document.exitFullscreen();
      break;
    default:
      break;
  }
}

// The display the program's window fits itself to: the page's room for the
// canvas, but never less than the 8514/A's 1024 x 768 and a margin, so that
// the program keeps a whole zoom of 1 or more (integer zoom, square pixels);
// a narrower page shows the canvas scaled down by the browser (style.css).
function viewport() {
  const r = $("screen").getBoundingClientRect();
  return [Math.max(1280, Math.floor(r.width)), Math.max(1024, Math.floor(window.innerHeight - 120))];
}

function startWorker() {
  return new Promise((resolve) => {
    worker = new Worker("worker.js");
    worker.onerror = (e) => showError(["the worker failed: " + (e.message || e)]);
    ring = new Int32Array(new SharedArrayBuffer(4 * (4 + kSlots * kSlotInts)));
    worker.onmessage = (e) => {
      const m = e.data;
      if (m.ready) resolve(m);
      else if (m.failed) showError(["the renderers did not start: " + m.failed]);
      else if (m.window) onWindow(m);
      else if (m.print !== undefined) log(m.print);
      else if (m.printErr !== undefined) log(m.printErr);
      else if (m.done !== undefined && pending) {
        const p = pending;
        pending = null;
        p(m);
      }
    };
    worker.postMessage({start: true, events: ring.buffer, viewport: viewport()});
  });
}

// Runs one command; resolves with the worker's answer.
function runPrime(args, files, want) {
  running = true;
  setBusy(true);
  $("command").textContent = "prime " + args.join(" ");
  return new Promise((resolve) => {
    pending = (m) => {
      running = false;
      setBusy(false);
      resolve(m);
    };
    worker.postMessage({run: args, files, want, viewport: viewport()});
  });
}

function setBusy(busy) {
  $("render").disabled = busy;
  $("walk").disabled = busy;
  $("stop").disabled = !busy;
}

async function fetchBytes(path) {
  const r = await fetch(path);
  if (!r.ok) throw new Error(path + ": " + r.status);
  return await r.arrayBuffer();
}

// The scene the controls name: its files for the program and its path there.
async function chosenScene() {
  const v = $("scene").value;
  if (v === "dropped" && dropped) return dropped;
  const [system, name] = v.split("/");
  const entry = scenes[system].find((s) => s.name === name);
  const files = {};
  await Promise.all(entry.files.map(async (f) => {
    files["/scenes/" + system + "/" + f] = await fetchBytes("scenes/" + system + "/" + f);
  }));
  return {system, name, files, target: "/scenes/" + system + "/" + entry.target};
}

function settingsArgs(system) {
  const args = [];
  if (system === "prime") {
    if ($("profile").value) args.push("--profile", $("profile").value);
    if ($("palette").value) args.push("--palette", $("palette").value);
    if ($("size").value) args.push("--size", ...$("size").value.split(" "));
    if ($("sampler").value) args.push(...$("sampler").value.split(" "));
  }
  if ($("pace").checked) args.push("--pace", "1991");
  if (!$("keep").checked) args.push("--no-wait");
  return args;
}

function setDownloads(files, names) {
  lastFiles = files;
  lastNames = names;
  for (const [id, path] of [["dl-graph", "/out/picture"], ["dl-png", "/out/picture-8514.png"],
                            ["dl-true", "/out/picture-true.png"]])
    $(id).disabled = !files[path];
}

async function render() {
  showError([]);
  $("log").textContent = "";
  const scene = await chosenScene();
  const isPrime = scene.system === "prime";
  const picture = "/out/picture";
  const args = ["trace", scene.target];
  if (isPrime) args.push("--model");
  args.push("--out", picture);
  args.push(isPrime ? "--png" : "--png-8514", "/out/picture-8514.png");
  args.push("--true-color-png", "/out/picture-true.png");
  args.push(...settingsArgs(scene.system));
  const m = await runPrime(args, scene.files,
                           [picture, "/out/picture-8514.png", "/out/picture-true.png"]);
  const base = scene.name.replace(/\.(mal|cgl)$/i, "");
  const pictureName = isPrime ? "graph_scr" : base + (scene.system === "malone" ? ".ppm" : ".rle");
  setDownloads(m.files, {[picture]: pictureName, "/out/picture-8514.png": base + "-8514.png",
                         "/out/picture-true.png": base + "-true.png"});
  finished(m);
}

async function walk() {
  showError([]);
  const scene = await chosenScene();
  const args = ["walk", scene.target];
  if (scene.system === "prime") args.push("--model");
  const m = await runPrime(args, scene.files, []);
  finished(m);
}

function finished(m) {
  if (m.done !== 0) {
    showError(m.err.length ? m.err : ["prime stopped with status " + m.done]);
    status("prime stopped with status " + m.done + " after " + (m.ms / 1000).toFixed(2) + " s");
  } else {
    status("done in " + (m.ms / 1000).toFixed(2) + " s");
  }
  window.primeLast = m;  // for the browser test (tests/web)
}

function download(path) {
  const blob = new Blob([lastFiles[path]]);
  const a = document.createElement("a");
  a.href = URL.createObjectURL(blob);
  a.download = lastNames[path];
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

// --- dropped scenes -------------------------------------------------------

async function unzip(buffer) {
  // A zip's central directory; stored and deflated entries (what zip tools write).
  const bytes = new Uint8Array(buffer);
  const view = new DataView(buffer);
  let end = -1;
  for (let i = bytes.length - 22; i >= Math.max(0, bytes.length - 65557); --i)
    if (view.getUint32(i, true) === 0x06054b50) { end = i; break; }
  if (end < 0) throw new Error("not a zip file (no end of central directory)");
  const count = view.getUint16(end + 10, true);
  let at = view.getUint32(end + 16, true);
  const files = {};
  for (let k = 0; k < count; ++k) {
    if (view.getUint32(at, true) !== 0x02014b50) throw new Error("a damaged zip central directory");
    const method = view.getUint16(at + 10, true);
    const size = view.getUint32(at + 20, true);
    const nameLength = view.getUint16(at + 28, true);
    const extra = view.getUint16(at + 30, true);
    const comment = view.getUint16(at + 32, true);
    const local = view.getUint32(at + 42, true);
    const name = new TextDecoder().decode(bytes.subarray(at + 46, at + 46 + nameLength));
    at += 46 + nameLength + extra + comment;
    if (name.endsWith("/")) continue;
    const start = local + 30 + view.getUint16(local + 26, true) + view.getUint16(local + 28, true);
    const data = bytes.subarray(start, start + size);
    if (method === 0) files[name] = data.slice().buffer;
    else if (method === 8)
      files[name] = await new Response(new Blob([data]).stream()
                                           .pipeThrough(new DecompressionStream("deflate-raw")))
                          .arrayBuffer();
    else throw new Error(name + ": zip method " + method + " (only stored and deflated are read)");
  }
  return files;
}

async function entryFiles(entry, prefix, out) {
  if (entry.isFile) {
    const file = await new Promise((ok, bad) => entry.file(ok, bad));
    out[prefix + entry.name] = await file.arrayBuffer();
  } else if (entry.isDirectory) {
    const reader = entry.createReader();
    for (;;) {
      const batch = await new Promise((ok, bad) => reader.readEntries(ok, bad));
      if (batch.length === 0) break;
      for (const e of batch) await entryFiles(e, prefix + entry.name + "/", out);
    }
  }
}

// files: relative path -> bytes, as dropped. Decides what the scene is.
async function takeScene(files) {
  for (const [path, bytes] of Object.entries(files))
    if (/\.zip$/i.test(path)) {
      delete files[path];
      Object.assign(files, await unzip(bytes));
    }
  const paths = Object.keys(files);
  const sceneFile = paths.find((p) => /\.(mal|cgl)$/i.test(p));
  const put = {};
  let target;
  let system;
  let name;
  if (sceneFile) {
    system = /\.mal$/i.test(sceneFile) ? "malone" : "cgl";
    const dir = sceneFile.includes("/") ? sceneFile.substring(0, sceneFile.lastIndexOf("/") + 1) : "";
    for (const p of paths) if (p.startsWith(dir)) put["/dropped/" + p.substring(dir.length)] = files[p];
    name = sceneFile.substring(dir.length);
    target = "/dropped/" + name;
  } else {
    // A PRIME scene directory: the deepest folder that holds the others' files
    // (Model.txt, prim/, obj/ ... ; a DOS copy may spell them in capitals).
    system = "prime";
    const tops = new Set(paths.map((p) => p.split("/")[0]));
    const inOne = tops.size === 1 && paths.every((p) => p.includes("/"));
    const root = inOne ? [...tops][0] + "/" : "";
    name = inOne ? [...tops][0] : "scene";
    for (const p of paths) put["/dropped/" + name + "/" + p.substring(root.length)] = files[p];
    target = "/dropped/" + name;
  }
  dropped = {system, name, files: put, target};
  let option = $("scene").querySelector("option[value=dropped]");
  if (!option) {
    option = document.createElement("option");
    option.value = "dropped";
    $("scene").prepend(option);
  }
  option.textContent = "Dropped: " + name + " (" + system + ")";
  $("scene").value = "dropped";
  sceneChanged();
  status("Took " + Object.keys(put).length + " file(s) as a " + system + " scene: " + name);
}

async function onDrop(e) {
  e.preventDefault();
  $("drop").classList.remove("over");
  const files = {};
  const items = [...e.dataTransfer.items].map((i) => i.webkitGetAsEntry()).filter((x) => x);
  for (const entry of items) await entryFiles(entry, "", files);
  await takeScene(files);
}

async function onPick(input) {
  const files = {};
  for (const f of input.files) files[f.webkitRelativePath || f.name] = await f.arrayBuffer();
  await takeScene(files);
  input.value = "";
}

function sceneChanged() {
  const v = $("scene").value;
  const system = v === "dropped" ? dropped.system : v.split("/")[0];
  for (const id of ["profile", "palette", "size", "sampler"]) $(id).disabled = system !== "prime";
}

// --- the canvas's keys and mouse, to the program --------------------------

function keyCode(e) {
  if (kNamedKeys[e.key]) return kNamedKeys[e.key];
  if (e.key.length === 1) return e.key.charCodeAt(0);
  return 0;
}

function setUpInput() {
  canvas.addEventListener("keydown", (e) => {
    if (!running) return;
    const code = keyCode(e);
    if (code === 0) return;
    e.preventDefault();
    event(kEvent.key, {code, shift: e.shiftKey});
  });
  const position = (e) => {
    const r = canvas.getBoundingClientRect();
    return {x: Math.floor((e.clientX - r.left) * canvas.width / r.width),
            y: Math.floor((e.clientY - r.top) * canvas.height / r.height)};
  };
  const buttonOf = (b) => (b === 0 ? 1 : b === 1 ? 2 : b === 2 ? 3 : 0);
  canvas.addEventListener("mousemove", (e) => {
    const p = position(e);
    const buttons = (e.buttons & 1 ? 1 : 0) | (e.buttons & 4 ? 2 : 0) | (e.buttons & 2 ? 4 : 0);
    event(kEvent.motion, {x: p.x, y: p.y, dx: p.x - lastX, dy: p.y - lastY, buttons});
    lastX = p.x;
    lastY = p.y;
    lastButtons = buttons;
  });
  canvas.addEventListener("mousedown", (e) => {
    canvas.focus();
    const p = position(e);
    event(kEvent.button, {x: p.x, y: p.y, button: buttonOf(e.button), down: true});
  });
  canvas.addEventListener("mouseup", (e) => {
    const p = position(e);
    event(kEvent.button, {x: p.x, y: p.y, button: buttonOf(e.button), down: false});
  });
  canvas.addEventListener("contextmenu", (e) => e.preventDefault());
  canvas.addEventListener("wheel", (e) => {
    e.preventDefault();
    event(kEvent.wheel, {wheel: e.deltaY < 0 ? 1 : -1});
  }, {passive: false});
}

async function main() {
  if (!window.crossOriginIsolated) {
    status("This page needs cross-origin isolation (its threads share memory): serve it with " +
           "./prime.sh web, or any server that sends Cross-Origin-Opener-Policy: same-origin " +
           "and Cross-Origin-Embedder-Policy: require-corp.");
    $("render").disabled = $("walk").disabled = true;
    return;
  }
  // The scene list is part of a build (build/web/): served from the sources
  // (web/) there is none, and the page says so instead of a JSON error.
  const list = await fetch("scenes/scenes.json");
  if (!list.ok || !(list.headers.get("Content-Type") || "").includes("json")) {
    status("scenes/scenes.json was not found: serve the built page (build/web/, made by " +
           "./prime.sh web --build-only) with python3 tools/web/serve.py build/web, not the " +
           "sources in web/.");
    $("render").disabled = $("walk").disabled = true;
    return;
  }
  scenes = await list.json();
  const select = $("scene");
  const titles = {prime: "PRIME (1991)", malone: "Malone (1995)", cgl: "Waterloo CGL (1985)"};
  for (const system of ["prime", "malone", "cgl"]) {
    const group = document.createElement("optgroup");
    group.label = titles[system];
    for (const s of scenes[system]) {
      const o = document.createElement("option");
      o.value = system + "/" + s.name;
      o.textContent = s.name;
      group.appendChild(o);
    }
    select.appendChild(group);
  }
  const first = new URLSearchParams(location.search).get("scene") || "prime/plate2";
  select.value = first;
  sceneChanged();
  select.addEventListener("change", sceneChanged);
  const ready = await startWorker();
  status("Ready: " + ready.threads + " thread(s). Pick a scene and Render.");
  $("render").onclick = render;
  $("walk").onclick = walk;
  $("stop").onclick = () => event(kEvent.quit);
  $("dl-graph").onclick = () => download("/out/picture");
  $("dl-png").onclick = () => download("/out/picture-8514.png");
  $("dl-true").onclick = () => download("/out/picture-true.png");
  const drop = $("drop");
  drop.addEventListener("dragover", (e) => {
    e.preventDefault();
    drop.classList.add("over");
  });
  drop.addEventListener("dragleave", () => drop.classList.remove("over"));
  drop.addEventListener("keydown", (e) => {  // the box from the keyboard: choose files
    if (e.key === "Enter" || e.key === " ") {
      e.preventDefault();
      $("pick").click();
    }
  });
  drop.addEventListener("drop", (e) => onDrop(e).catch((x) => showError([String(x)])));
  $("pick").addEventListener("change", (e) => onPick(e.target).catch((x) => showError([String(x)])));
  $("pickdir").addEventListener("change",
                                (e) => onPick(e.target).catch((x) => showError([String(x)])));
  setUpInput();
  window.primePage = {render, walk, takeScene, runPrime, ready: true};  // for tests/web
}

main().catch((e) => showError([String(e)]));
