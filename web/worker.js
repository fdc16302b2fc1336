// The page's worker: runs `prime` (prime-page.js, the same program as the
// command line, compiled to WebAssembly) command after command, off the
// page's thread. The page sends {run: [args], files: {path: bytes}, want:
// [paths]}; the worker writes the files into the program's memory file
// system, runs the command, and answers {done: status, files: {path: bytes},
// out, err}. While a command runs, what its window shows goes to the page as
// it is drawn (web_window_module.cpp calls Module.primeWindow), and the
// page's keys and mouse come back through `events`, a SharedArrayBuffer ring.
"use strict";
importScripts("prime-page.js");

let prime = null;
let out = [];
let err = [];

function send(message, transfer) {
  postMessage(message, transfer || []);
}

function windowCall(kind, a, b, c, d, rows) {
  if (kind === "rect") {
    send({window: kind, x: a, y: b, w: c, h: d, rows}, [rows.buffer]);
  } else if (kind === "title") {
    send({window: kind, text: a});
  } else {
    send({window: kind, a, b, c, d});
  }
}

function ensureDirectory(FS, path) {
  const parts = path.split("/").filter((p) => p);
  let at = "";
  for (const p of parts) {
    at += "/" + p;
    try {
      FS.mkdir(at);
    } catch (e) {
      // exists
    }
  }
}

async function start(message) {
  prime = await createPrime({
    primeWindow: windowCall,
    primeEvents: message.events ? new Int32Array(message.events) : null,
    primeViewport: message.viewport,
    print: (line) => {
      out.push(line);
      send({print: line});
    },
    printErr: (line) => {
      err.push(line);
      send({printErr: line});
    },
    locateFile: (name) => name,
    // Where the program's own threads load it from (a worker has no
    // document.currentScript for emscripten to find it by).
    mainScriptUrlOrBlob: new URL("prime-page.js", self.location.href).href,
  });
  send({ready: true, threads: navigator.hardwareConcurrency});
}

function run(message) {
  const FS = prime.FS;
  for (const [path, bytes] of Object.entries(message.files || {})) {
    ensureDirectory(FS, path.substring(0, path.lastIndexOf("/")));
    FS.writeFile(path, new Uint8Array(bytes));
  }
  for (const path of message.want || []) {
    ensureDirectory(FS, path.substring(0, path.lastIndexOf("/")));
    try {
      FS.unlink(path);  // not last command's
    } catch (e) {
      // not there
    }
  }
  for (const path of message.remove || []) {
    try {
      FS.unlink(path);
    } catch (e) {
      // not there
    }
  }
  if (message.viewport) prime.primeViewport = message.viewport;
  out = [];
  err = [];
  const started = performance.now();
  let status = 0;
  try {
    status = prime.callMain(message.run);
  } catch (e) {
    status = typeof e.status === "number" ? e.status : 1;
    if (typeof e.status !== "number") err.push(String(e));
  }
  const files = {};
  const transfer = [];
  for (const path of message.want || []) {
    try {
      const bytes = FS.readFile(path);
      files[path] = bytes;
      transfer.push(bytes.buffer);
    } catch (e) {
      // not written
    }
  }
  send({done: status, files, out, err, ms: performance.now() - started}, transfer);
}

onmessage = (e) => {
  if (e.data.start) start(e.data).catch((x) => send({failed: String(x && x.stack || x)}));
  else if (e.data.run) run(e.data);
};
