// The scene picker: built-in and uploaded scenes from GET /v1/scenes, and uploading a .glb
// (or a self-contained .gltf) with POST /v1/scenes, which answers the new scene's report.

import { listScenes, uploadScene } from './api_client.js';

export class ScenePicker {
  #reports = new Map();  // id -> the scene's report (camera, lights, bounds)

  constructor({ select, fileInput, state, onError }) {
    Object.assign(this, { select, fileInput, state, onError });
    fileInput.addEventListener('change', () => this.#upload());
    state.addEventListener('change', () => this.#reportCurrentScene());
  }

  async load() {
    const scenes = await listScenes();
    this.#reports = new Map(scenes.map((scene) => [scene.id, scene]));
    const groups = [['builtin', 'Built-in'], ['uploaded', 'Uploaded']].map(([source, label]) => {
      const group = document.createElement('optgroup');
      group.label = label;
      for (const scene of scenes.filter((s) => s.source === source)) {
        const option = new Option(scene.source === 'uploaded' ? `${scene.name} (${scene.triangles} triangles)` : scene.name, scene.id);
        option.title = scene.description || scene.id;
        group.append(option);
      }
      return group;
    });
    this.select.replaceChildren(...groups.filter((group) => group.children.length));
    this.select.value = this.state.get('scene');
    this.#reportCurrentScene();
  }

  // The state needs the current scene's report for its default camera and lights.
  #reportCurrentScene() {
    const report = this.#reports.get(this.state.get('scene')) ?? null;
    if (report !== this.state.sceneReport()) this.state.setSceneReport(report);
  }

  async #upload() {
    const [file] = this.fileInput.files;
    if (!file) return;
    try {
      const report = await uploadScene(file);
      await this.load();
      this.state.setScene(report.id);
    } catch (error) {
      this.onError(Object.assign(error, { field: 'upload' }));  // shown next to the file input
    } finally {
      this.fileInput.value = '';
    }
  }
}
