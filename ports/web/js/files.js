// files.js — scene and replay files: the scene picker, recording download, replay
// loading (a chosen file or one shipped with the page) and the playback buttons.
//
// The files come from manifest.json (written by scripts/build-web.sh from scenes/ and
// tests/replays/). A file that fails to load leaves the app as it was; the app's
// message (the reader's error with its line, or its offset and field) is shown.
import { boundsOf } from './view.js';
import { refocus } from './controls.js';

const $ = (id) => document.getElementById(id);
const baseName = (path) => path.split('/').pop();

async function fetchBytes(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
  return new Uint8Array(await response.arrayBuffer());
}

export class Files {
  constructor(engine, view, canvas, loop, notes) {
    this.engine = engine;
    this.view = view;
    this.canvas = canvas;
    this.loop = loop;
    this.notes = notes;          // {localMessage}: the page's own messages (fetch errors)
    this.playbackSpeed = 1;      // replay frames per tick; 0: as many as fit in a display frame
    this.manifest = { scenes: [], replays: [] };
  }

  fit() { this.view.fit(boundsOf(this.engine.drawList())); }

  async loadScene(path) {
    const text = new TextDecoder().decode(await fetchBytes(path));
    const name = baseName(path).replace(/\.scene$/, '');
    const r = this.engine.loadScene(name, text);
    if (r === 0) {
      this.fit();
      this.loop.reset();
      $('scene').value = path;
    }
    return r;
  }

  async playBytes(bytes) {
    const r = this.engine.playReplay(bytes);
    if (r === 0) {
      this.fit();
      this.loop.reset();
    }
    return r;
  }

  download() {
    const bytes = this.engine.recording();
    if (!bytes) {
      this.notes.localMessage = this.engine.message() || 'No recording: load a scene first';
      return;
    }
    const link = document.createElement('a');
    link.href = URL.createObjectURL(new Blob([bytes], { type: 'application/octet-stream' }));
    link.download = `pogon-${this.engine.sceneName() || 'session'}.pgr`;
    document.body.appendChild(link);
    link.click();
    link.remove();
    setTimeout(() => URL.revokeObjectURL(link.href), 10000);
  }

  async init() {
    this.manifest = await (await fetch('manifest.json')).json();
    const scene = $('scene');
    for (const path of this.manifest.scenes) scene.add(new Option(baseName(path).replace(/\.scene$/, ''), path));
    const shipped = $('replay-shipped');
    for (const path of this.manifest.replays) shipped.add(new Option(path.replace(/^replays\//, ''), path));

    const guard = (fn) => async (e) => {
      try {
        await fn(e);
      } catch (err) {
        this.notes.localMessage = String(err.message || err);
      }
      refocus(this.canvas, e.target);
    };
    scene.addEventListener('change', guard(() => this.loadScene(scene.value)));
    $('download').addEventListener('click', guard(() => this.download()));
    $('replay-file').addEventListener('change', guard(async (e) => {
      const file = e.target.files[0];
      if (file) await this.playBytes(new Uint8Array(await file.arrayBuffer()));
      e.target.value = ''; // the same file can be chosen again
    }));
    $('replay-play-shipped').addEventListener('click', guard(async () => {
      if (shipped.value) await this.playBytes(await fetchBytes(shipped.value));
    }));
    $('pb-run').addEventListener('click', guard(() => this.engine.setPaused(!this.engine.paused())));
    $('pb-step').addEventListener('click', guard(() => {
      if (!this.engine.paused()) this.engine.setPaused(true);
      this.engine.stepOnce();
    }));
    $('pb-speed').addEventListener('change', guard((e) => { this.playbackSpeed = Number(e.target.value); }));
    $('pb-stop').addEventListener('click', guard(() => this.engine.stopPlayback()));

    const start = this.manifest.scenes.find((p) => p.endsWith('/demo.scene')) || this.manifest.scenes[0];
    if (start) await this.loadScene(start);
  }
}
