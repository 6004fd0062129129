// The 3D view of report.html: three.js with GLTFLoader and OrbitControls, bundled by esbuild into
// viewer.bundle.js (one classic script: a page opened from file:// may not import modules), which
// defines window.CoolingGenViewer. The page (report_page.js) hands it the .glb bytes and the face table
// (primitive i -> face name, kind, body, area) and reads back what it drew.
import {
  AmbientLight, Box3, HemisphereLight, Color, DirectionalLight, DoubleSide, PerspectiveCamera, Raycaster, Scene, Sphere,
  Vector2, Vector3, WebGLRenderer,
} from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';

const CLEAR = 0xf4f5f7;  // the canvas' clear colour: pixels of another colour are the model's

function bytesOf(base64) {
  const text = atob(base64);
  const bytes = new Uint8Array(text.length);
  for (let i = 0; i < text.length; ++i) bytes[i] = text.charCodeAt(i);
  return bytes.buffer;
}

function parse(buffer) {
  return new Promise((resolve, reject) => new GLTFLoader().parse(buffer, '', resolve, reject));
}

class Viewer {
  constructor(canvas, gltf, faces, up) {
    this.canvas = canvas;
    this.faces = faces;
    this.renderer = new WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(1);
    this.renderer.setClearColor(CLEAR, 1);
    this.scene = new Scene();
    this.scene.background = new Color(CLEAR);
    this.scene.add(gltf.scene);
    this.meshes = [];
    gltf.scene.traverse((o) => { if (o.isMesh) this.meshes.push(o); });
    if (this.meshes.length !== faces.length)
      throw new Error(`the model has ${this.meshes.length} primitives, the face table ${faces.length}`);
    this.meshes.forEach((m, i) => {
      m.userData.face = i;
      m.material.side = DoubleSide;
    });
    this.camera = new PerspectiveCamera(35, 1, 1e-4, 100);
    if (up && up.length === 3) this.camera.up.set(up[0], up[1], up[2]).normalize();
    this.scene.add(new AmbientLight(0xffffff, 0.6));
    this.scene.add(new HemisphereLight(0xffffff, 0x8a8f99, 0.9));
    const key = new DirectionalLight(0xffffff, 2.2);
    key.position.set(0.4, 0.7, 1);
    this.camera.add(key);
    this.scene.add(this.camera);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.addEventListener('change', () => this.render());
    this.resize();
    this.fit();
  }

  resize() {
    const w = Math.max(1, this.canvas.clientWidth), h = Math.max(1, this.canvas.clientHeight);
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
  }

  // The whole part in view, upright (the camera's up is the blade's hub -> tip direction), seen from
  // the side and a little from above the tip.
  fit() {
    const sphere = new Box3().setFromObject(this.scene).getBoundingSphere(new Sphere());
    const d = (sphere.radius / Math.sin((this.camera.fov * Math.PI) / 360)) * 0.9;
    const up = this.camera.up;
    const axes = [new Vector3(1, 0, 0), new Vector3(0, 1, 0), new Vector3(0, 0, 1)];
    const across = axes.sort((a, b) => Math.abs(a.dot(up)) - Math.abs(b.dot(up)))[0];
    const side = across.clone().addScaledVector(up, -across.dot(up)).normalize();
    const dir = side.clone().add(new Vector3().crossVectors(up, side).multiplyScalar(0.6)).addScaledVector(up, 0.5).normalize();
    this.camera.position.copy(sphere.center).addScaledVector(dir, d);
    this.camera.near = d / 100;
    this.camera.far = d * 10;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(sphere.center);
    this.controls.update();
  }

  render() {
    this.renderer.render(this.scene, this.camera);
  }

  // Pixels whose colour differs from the clear colour (read back from the drawing buffer).
  drawnPixels() {
    const gl = this.renderer.getContext();
    const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
    const px = new Uint8Array(w * h * 4);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
    const ref = [(CLEAR >> 16) & 255, (CLEAR >> 8) & 255, CLEAR & 255];  // sRGB, as the canvas holds it
    let n = 0;
    for (let i = 0; i < px.length; i += 4)
      if (Math.abs(px[i] - ref[0]) > 3 || Math.abs(px[i + 1] - ref[1]) > 3 || Math.abs(px[i + 2] - ref[2]) > 3) ++n;
    return n;
  }

  setVisible(test, on) {
    this.meshes.forEach((m, i) => { if (test(this.faces[i])) m.visible = on; });
    this.render();
  }

  // The face index under canvas pixel (x, y) (CSS pixels from the top left), or -1.
  pick(x, y) {
    const ndc = new Vector2((x / this.canvas.clientWidth) * 2 - 1, 1 - (y / this.canvas.clientHeight) * 2);
    const ray = new Raycaster();
    ray.setFromCamera(ndc, this.camera);
    const hit = ray.intersectObjects(this.meshes.filter((m) => m.visible), false)[0];
    return hit ? hit.object.userData.face : -1;
  }

  // A point of face i on screen (CSS pixels): the centroid of its largest triangle facing the camera,
  // projected; null when none faces the camera.
  facePoint(i) {
    const m = this.meshes[i];
    const pos = m.geometry.attributes.position, index = m.geometry.index;
    const count = index ? index.count : pos.count;
    const a = new Vector3(), b = new Vector3(), c = new Vector3(), n = new Vector3(), e = new Vector3();
    let best = null, bestArea = 0;
    for (let t = 0; t + 2 < count; t += 3) {
      const k = (j) => (index ? index.getX(t + j) : t + j);
      a.fromBufferAttribute(pos, k(0)).applyMatrix4(m.matrixWorld);
      b.fromBufferAttribute(pos, k(1)).applyMatrix4(m.matrixWorld);
      c.fromBufferAttribute(pos, k(2)).applyMatrix4(m.matrixWorld);
      n.subVectors(b, a).cross(e.subVectors(c, a));
      const centre = a.clone().add(b).add(c).multiplyScalar(1 / 3);
      const toward = this.camera.position.clone().sub(centre);
      if (n.dot(toward) <= 0 || n.length() <= bestArea) continue;
      bestArea = n.length();
      best = centre;
    }
    if (!best) return null;
    const p = best.project(this.camera);
    return { x: ((p.x + 1) / 2) * this.canvas.clientWidth, y: ((1 - p.y) / 2) * this.canvas.clientHeight };
  }
}

// Opens the model; resolves to the viewer (rendered once) or rejects with the reason it is broken.
// `up`: the blade's hub -> tip direction in the model's (glTF) axes.
async function open(canvas, base64, faces, up) {
  const gltf = await parse(bytesOf(base64));
  const v = new Viewer(canvas, gltf, faces, up);
  v.render();
  return v;
}

window.CoolingGenViewer = { open };
