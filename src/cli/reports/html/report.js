// The report page's script: reads the data polymass wrote into the page
// (#polymass-data, the arrays #polymass-blob-N) and draws it with three.js.
// Three views, by data.kind: "check" (each mesh with every finding's
// locations, and the findings as a table whose rows select them),
// "properties" (the mesh, its centre of mass, principal axes and equivalent
// inertia box) and "audit" (each link's geometry, declared and computed
// centres of mass and equivalent inertia boxes, findings by severity).
//
// window.polymass is the page's state, read by the tests (tests/browser):
// ready, errors, what is drawn (drawn, boxes), and project/pixelAt to find
// a point of the model on the canvas.
'use strict';

(function () {
  const state = {
    ready: false,
    errors: [],
    kind: null,
    file: 0,
    drawn: [], // the findings' locations as drawn: {key, index, what, points}
    boxes: [], // equivalent inertia boxes: {link, which, sides, center, axes, clamped}
    notes: [],
  };
  window.polymass = state;
  window.addEventListener('error', (event) => state.errors.push(String(event.message)));

  // ---- data ---------------------------------------------------------------

  const data = JSON.parse(document.getElementById('polymass-data').textContent);
  state.kind = data.kind;

  const BASE64 = 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/';
  const BASE64_VALUE = new Uint8Array(128);
  for (let i = 0; i < BASE64.length; i++) BASE64_VALUE[BASE64.charCodeAt(i)] = i;

  // The bytes of an array the page carries (RFC 4648 base64, padded).
  function blobBytes(id) {
    const text = document.getElementById(id).textContent;
    const padding = text.endsWith('==') ? 2 : text.endsWith('=') ? 1 : 0;
    const bytes = new Uint8Array((text.length / 4) * 3 - padding);
    let out = 0;
    for (let i = 0; i < text.length; i += 4) {
      const group =
        (BASE64_VALUE[text.charCodeAt(i)] << 18) |
        (BASE64_VALUE[text.charCodeAt(i + 1)] << 12) |
        (BASE64_VALUE[text.charCodeAt(i + 2)] << 6) |
        BASE64_VALUE[text.charCodeAt(i + 3)];
      bytes[out++] = group >> 16;
      if (out < bytes.length) bytes[out++] = (group >> 8) & 255;
      if (out < bytes.length) bytes[out++] = group & 255;
    }
    return bytes.buffer;
  }
  const floats = (id) => new Float32Array(blobBytes(id));
  const uint32s = (id) => new Uint32Array(blobBytes(id));

  // ---- page helpers -------------------------------------------------------

  function el(tag, attributes, ...children) {
    const element = document.createElement(tag);
    for (const [name, value] of Object.entries(attributes || {})) {
      if (value === undefined || value === null || value === false) continue;
      if (name === 'dataset') Object.assign(element.dataset, value);
      else if (name === 'onclick') element.addEventListener('click', value);
      else element.setAttribute(name, value === true ? '' : value);
    }
    for (const child of children.flat()) {
      if (child === null || child === undefined) continue;
      element.append(child instanceof Node ? child : String(child));
    }
    return element;
  }

  // Six significant digits on the page; every digit in the title (tooltip).
  function number(value) {
    if (value === null || value === undefined) return '—';
    if (value === 0) return '0';
    const magnitude = Math.abs(value);
    return magnitude >= 1e-4 && magnitude < 1e7
      ? String(Number(value.toPrecision(6)))
      : value.toExponential(5).replace(/\.?0+e/, 'e');
  }
  const numberCell = (value) => el('td', { class: 'number', title: String(value) }, number(value));
  const vectorText = (v) => '(' + v.map(number).join(', ') + ')';
  const plural = (count, word, words) => count + ' ' + (count === 1 ? word : words || word + 's');

  function table(headings, rows) {
    return el('table', {}, el('tr', {}, headings.map((h) => el('th', {}, h))), rows);
  }

  function setNotes(notes) {
    state.notes = notes;
    const box = document.getElementById('view-notes');
    box.replaceChildren(...notes.map((note) => el('div', {}, note)));
  }

  function setLegend(entries) {
    const box = document.getElementById('legend');
    box.replaceChildren(
      ...entries.map(([colour, text]) =>
        el('span', {}, el('span', { class: 'swatch', style: 'background:' + colour }), text)
      )
    );
  }

  // ---- the 3D view --------------------------------------------------------

  const DEFAULT_DIRECTION = new THREE.Vector3(1.0, -1.4, 0.9).normalize();

  // The default view, turned towards a side of the model where there is
  // something to see (the findings' middle, seen from outside).
  function lookTowards(point, center) {
    const side = point.clone().sub(center);
    if (side.length() === 0) return DEFAULT_DIRECTION.clone();
    return side.normalize().add(DEFAULT_DIRECTION.clone().multiplyScalar(0.6)).normalize();
  }

  class Viewer {
    constructor(canvas) {
      this.canvas = canvas;
      this.renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
      this.renderer.setPixelRatio(window.devicePixelRatio || 1);
      this.scene = new THREE.Scene();
      this.scene.background = new THREE.Color(0xf4f6f8);
      this.camera = new THREE.PerspectiveCamera(35, 1, 1e-3, 1e3);
      this.camera.up.set(0, 0, 1); // z up, as robot descriptions and most CAD
      this.scene.add(this.camera);
      this.scene.add(new THREE.HemisphereLight(0xffffff, 0x8090a0, 0.75));
      const headlight = new THREE.DirectionalLight(0xffffff, 0.55);
      headlight.position.set(0.5, 1, 1);
      this.camera.add(headlight);
      this.content = new THREE.Group();
      this.scene.add(this.content);
      this.controls = new THREE.OrbitControls(this.camera, canvas);
      this.controls.addEventListener('change', () => this.render());
      this.home = new THREE.Sphere(new THREE.Vector3(), 1);
      this.homeDirection = DEFAULT_DIRECTION.clone();
      new ResizeObserver(() => this.resize()).observe(canvas);
      window.addEventListener('keydown', (event) => {
        if (event.key === 'r' && event.target === document.body) this.frame(this.home, true);
      });
    }

    resize() {
      const width = Math.max(1, this.canvas.clientWidth);
      const height = Math.max(1, this.canvas.clientHeight);
      this.renderer.setSize(width, height, false);
      this.camera.aspect = width / height;
      this.camera.updateProjectionMatrix();
      this.render();
    }

    clear() {
      for (const child of [...this.content.children]) {
        this.content.remove(child);
        child.traverse((object) => {
          if (object.geometry) object.geometry.dispose();
          if (object.material) object.material.dispose();
        });
      }
    }

    // Points the camera at sphere, from the default direction when reset.
    frame(sphere, reset) {
      const radius = Math.max(sphere.radius, 1e-9);
      const direction = reset ? this.homeDirection.clone() : this.camera.position.clone().sub(this.controls.target).normalize();
      const fov = (this.camera.fov * Math.PI) / 180;
      const distance = (1.15 * radius) / Math.sin(fov / 2) / Math.min(1, this.camera.aspect);
      this.controls.target.copy(sphere.center);
      this.camera.position.copy(sphere.center).addScaledVector(direction, distance);
      const homeRadius = Math.max(this.home.radius, radius);
      this.camera.near = Math.max(distance - 4 * homeRadius, distance * 1e-3);
      this.camera.far = distance + 4 * homeRadius;
      this.camera.updateProjectionMatrix();
      this.controls.update();
      this.render();
    }

    render() {
      this.renderer.render(this.scene, this.camera);
    }

    // Where a scene point falls on the canvas, in CSS pixels from its
    // top-left corner.
    project(point) {
      const v = new THREE.Vector3(...point).project(this.camera);
      return { x: ((v.x + 1) / 2) * this.canvas.clientWidth, y: ((1 - v.y) / 2) * this.canvas.clientHeight };
    }

    // The RGBA of the drawn canvas at CSS pixel (x, y).
    pixelAt(x, y) {
      const gl = this.renderer.getContext();
      const ratio = this.renderer.getPixelRatio();
      const pixel = new Uint8Array(4);
      gl.readPixels(
        Math.round(x * ratio),
        Math.round(gl.drawingBufferHeight - 1 - y * ratio),
        1,
        1,
        gl.RGBA,
        gl.UNSIGNED_BYTE,
        pixel
      );
      return Array.from(pixel);
    }
  }

  const viewer = new Viewer(document.getElementById('canvas'));
  state.project = (point) => viewer.project(toScene(point));
  state.pixelAt = (x, y) => viewer.pixelAt(x, y);
  // Where the view looks (the point it orbits), in file coordinates.
  state.target = () => viewer.controls.target.toArray().map((x, axis) => x + origin[axis]);

  // Scene coordinates are the file's less this origin (float32 keeps the
  // detail of a part far from the origin).
  let origin = [0, 0, 0];
  const toScene = (p) => [p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]];
  const vector = (p) => new THREE.Vector3(...toScene(p));

  // ---- meshes -------------------------------------------------------------

  const SOLID_COLOUR = 0xb4c0cc;
  const BACK_COLOUR = 0xe8893a; // the inside of the surface, seen through a hole or a flipped face

  // A page mesh (reports/html_mesh.hpp) as three.js objects, in the scene's
  // coordinates (its positions are relative to mesh.origin).
  function buildMesh(mesh, options) {
    const positions = floats(mesh.positions);
    const shift = toScene(mesh.origin);
    if (shift.some((x) => x !== 0)) {
      for (let i = 0; i < positions.length; i++) positions[i] += shift[i % 3];
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    geometry.setIndex(new THREE.BufferAttribute(uint32s(mesh.triangles), 1));
    geometry.computeBoundingSphere();
    const opacity = options.opacity === undefined ? 1 : options.opacity;
    const material = (colour, side) =>
      new THREE.MeshPhongMaterial({
        color: colour,
        flatShading: true,
        side,
        transparent: opacity < 1,
        opacity,
        depthWrite: opacity === 1,
        polygonOffset: true,
        polygonOffsetFactor: 1,
        polygonOffsetUnits: 1,
      });
    const solid = new THREE.Group();
    solid.add(new THREE.Mesh(geometry, material(options.colour || SOLID_COLOUR, THREE.FrontSide)));
    // Opaque, the inside shows only through a hole or a flipped face; see-through, it
    // is the same surface.
    solid.add(new THREE.Mesh(geometry, material(opacity < 1 ? options.colour || SOLID_COLOUR : BACK_COLOUR, THREE.BackSide)));
    const wireframe = new THREE.Mesh(
      geometry,
      new THREE.MeshBasicMaterial({ color: 0x2b3440, wireframe: true, transparent: true, opacity: 0.35 })
    );
    return {
      mesh,
      positions,
      geometry,
      solid,
      wireframe,
      triangleFaces: uint32s(mesh.triangle_faces),
      faceShells: mesh.face_shells ? uint32s(mesh.face_shells) : null,
      // A shown corner (a triangles index), in scene coordinates.
      corner(i) {
        return [positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]];
      },
      // A vertex a finding names (by the file's number), in scene
      // coordinates; null for one the page was not given.
      point(v) {
        const p = mesh.located_vertices[String(v)];
        return p ? p.map((x, axis) => x + shift[axis]) : null;
      },
    };
  }

  const shown = { solid: true, wireframe: false };
  const meshViews = [];
  function showMesh(view) {
    view.solid.visible = shown.solid;
    view.wireframe.visible = shown.wireframe;
    meshViews.push(view);
    viewer.content.add(view.solid, view.wireframe);
  }
  document.getElementById('show-solid').addEventListener('change', (event) => {
    shown.solid = event.target.checked;
    for (const view of meshViews) view.solid.visible = shown.solid;
    viewer.render();
  });
  document.getElementById('show-wireframe').addEventListener('change', (event) => {
    shown.wireframe = event.target.checked;
    for (const view of meshViews) view.wireframe.visible = shown.wireframe;
    viewer.render();
  });
  document.getElementById('reset-view').addEventListener('click', () => viewer.frame(viewer.home, true));

  function decimationNote(mesh) {
    if (!mesh || !mesh.decimated) return [];
    return [
      'Drawn decimated: ' +
        mesh.shown_triangles.toLocaleString('en') +
        ' of ' +
        mesh.triangle_count.toLocaleString('en') +
        ' triangles shown (vertices merged on a grid); the numbers and the findings are those of the full mesh.',
    ];
  }

  // A toolbar check box that shows or hides object.
  function toggle(label, object, checked) {
    object.visible = checked;
    const input = el('input', { type: 'checkbox', checked });
    input.addEventListener('change', () => {
      object.visible = input.checked;
      viewer.render();
    });
    document.getElementById('toolbar-extra').append(el('label', {}, input, ' ' + label));
  }

  // The convex hull of the vertices the mesh's triangles use (three.js's
  // ConvexBufferGeometry), drawn over the mesh when the hull answered.
  function hullObject(view) {
    const used = new Set(view.geometry.index.array);
    const points = [...used].map((i) => new THREE.Vector3(...view.corner(i)));
    const group = new THREE.Group();
    const geometry = new THREE.ConvexBufferGeometry(points);
    group.add(
      new THREE.Mesh(
        geometry,
        new THREE.MeshBasicMaterial({ color: 0x2e9e5b, transparent: true, opacity: 0.18, depthWrite: false })
      )
    );
    group.add(new THREE.LineSegments(new THREE.EdgesGeometry(geometry), new THREE.LineBasicMaterial({ color: 0x2e9e5b })));
    return group;
  }

  // ---- overlays -------------------------------------------------------------

  // Drawn over everything (no depth test): a finding hidden behind the
  // surface is still seen.
  const overlayMaterial = (colour, opacity) =>
    new THREE.MeshBasicMaterial({
      color: colour,
      transparent: true,
      opacity: opacity || 1,
      depthTest: false,
      depthWrite: false,
      side: THREE.DoubleSide,
    });

  // Drawn after the see-through surfaces and over everything.
  function onTop(object, order) {
    object.traverse((child) => {
      if (child.material) {
        child.material.depthTest = false;
        child.material.transparent = true;
      }
      child.renderOrder = order;
    });
    return object;
  }

  function tube(a, b, radius, material) {
    const start = new THREE.Vector3(...a);
    const end = new THREE.Vector3(...b);
    const length = start.distanceTo(end);
    const group = new THREE.Group();
    const cylinder = new THREE.Mesh(new THREE.CylinderBufferGeometry(radius, radius, length, 10, 1), material);
    cylinder.position.copy(start).add(end).multiplyScalar(0.5);
    if (length > 0) {
      cylinder.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), end.clone().sub(start).normalize());
    }
    group.add(cylinder);
    for (const p of [start, end]) group.add(dot(p, 1.6 * radius, material));
    return group;
  }

  function dot(position, radius, material) {
    const sphere = new THREE.Mesh(new THREE.SphereBufferGeometry(radius, 16, 12), material);
    sphere.position.copy(position);
    return sphere;
  }

  // Triangles (fans of the polygons given as corner lists, each corner's
  // point by pointOf) as one mesh; polygons with a corner the mesh lacks are
  // left out.
  function polygons(pointOf, corners, material) {
    const vertices = [];
    for (const polygon of corners) {
      const points = polygon.map(pointOf);
      if (points.length < 3 || points.some((p) => !p || p.some((x) => !Number.isFinite(x)))) continue;
      for (let k = 1; k + 1 < points.length; k++) vertices.push(...points[0], ...points[k], ...points[k + 1]);
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(vertices, 3));
    return new THREE.Mesh(geometry, material);
  }

  // The shown triangles of a shell, as corners.
  function shellTriangles(view, shell) {
    const index = view.geometry.index.array;
    const corners = [];
    for (let t = 0; t < view.triangleFaces.length; t++) {
      if (view.faceShells[view.triangleFaces[t]] === shell) corners.push([index[3 * t], index[3 * t + 1], index[3 * t + 2]]);
    }
    return corners;
  }

  // Selection: the drawn objects of the selected rows at full strength, the
  // others faded, the camera framing the selection.
  let selectable = []; // {row, objects, sphere}
  function select(entry) {
    const already = entry && entry.row.classList.contains('selected');
    for (const other of selectable) {
      other.row.classList.remove('selected');
      for (const object of other.objects) object.traverse(fade(already || !entry ? 1 : 0.15));
    }
    if (!entry || already) {
      viewer.frame(viewer.home, false);
      return;
    }
    entry.row.classList.add('selected');
    for (const object of entry.objects) object.traverse(fade(1));
    viewer.frame(entry.sphere || viewer.home, false);
  }
  const fade = (strength) => (object) => {
    if (!object.material) return;
    if (object.userData.opacity === undefined) object.userData.opacity = object.material.opacity;
    object.material.opacity = object.userData.opacity * strength;
    object.material.transparent = true;
  };
  function makeSelectable(row, objects, sphere) {
    const entry = { row, objects, sphere };
    row.classList.add('selectable');
    row.addEventListener('click', () => select(entry));
    selectable.push(entry);
    return entry;
  }
  function sphereOf(objects, minimum) {
    const box = new THREE.Box3();
    for (const object of objects) box.expandByObject(object);
    const sphere = box.getBoundingSphere(new THREE.Sphere());
    sphere.radius = Math.max(sphere.radius, minimum);
    return sphere;
  }

  // ---- polymass check ---------------------------------------------------

  // The labels of the table polymass check prints, and each kind's colour.
  const CHECK_KINDS = {
    open_edges: ['open edges', '#e6194b'],
    non_manifold_edges: ['non-manifold edges', '#d81bd8'],
    misoriented_edges: ['misoriented edges', '#f58231'],
    non_planar_faces: ['non-planar faces', '#8e44ad'],
    degenerate_faces: ['degenerate faces', '#00a6a6'],
    small_faces: ['faces < 3 vertices', '#7a9a00'],
    out_of_range_indices: ['bad vertex indices', '#555555'],
    non_finite_vertices: ['non-finite vertices', '#555555'],
    intersecting_face_pairs: ['crossing face pairs', '#e6194b'],
    touching_face_pairs: ['touching face pairs', '#1f6fd1'],
    inverted_shells: ['inside-out shells', '#16a085'],
    overlapping_shells: ['overlapping shells', '#8e44ad'],
  };
  const SECOND_FACE_COLOUR = '#f2c200';
  // Which list names a finding's locations, and what they are.
  const LOCATION_LISTS = {
    first_edges: 'edge',
    first_faces: 'face',
    first_pairs: 'pair',
    first_shells: 'shell',
    first_vertices: 'vertex',
  };

  // The findings of a check report: every member that has a count, as
  // --json gives it, in its order.
  function findingsOf(report) {
    const findings = [];
    for (const [key, value] of Object.entries(report)) {
      if (!value || typeof value !== 'object' || Array.isArray(value) || !('count' in value)) continue;
      const list = Object.keys(value).find((name) => name in LOCATION_LISTS);
      findings.push({ key, count: value.count, where: LOCATION_LISTS[list], locations: list ? value[list] : [], value });
    }
    return findings;
  }

  function shellOfFace(view, face) {
    return view && view.faceShells && face < view.faceShells.length ? view.faceShells[face] : null;
  }

  function locationText(finding, location, view) {
    const vertexText = (v) => {
      const p = view && view.point(v);
      return 'vertex ' + v + (p ? ' ' + vectorText(p.map((x, axis) => x + origin[axis])) : '');
    };
    const faceText = (f) => {
      const shell = shellOfFace(view, f);
      return 'face ' + f + (shell === null ? '' : ' (shell ' + shell + ')');
    };
    switch (finding.where) {
      case 'edge':
        return 'edge ' + vertexText(location[0]) + ' – ' + vertexText(location[1]);
      case 'pair':
        return faceText(location[0]) + ' and ' + faceText(location[1]);
      case 'shell':
        return 'shell ' + location;
      case 'vertex':
        return 'vertex ' + location + ' (not drawn: not a finite point)';
      default:
        return faceText(location);
    }
  }

  // The objects that draw one location of a finding (none for what has no
  // place: a non-finite vertex, a face naming a vertex that does not exist).
  function drawLocation(view, finding, location, radius) {
    const colour = (CHECK_KINDS[finding.key] || [null, '#555555'])[1];
    const objects = [];
    let points = [];
    const located = (face) => view.mesh.located_faces[String(face)] || [];
    if (finding.where === 'edge') {
      const a = view.point(location[0]);
      const b = view.point(location[1]);
      if (a && b) {
        objects.push(tube(a, b, radius, overlayMaterial(colour)));
        points = [a, b];
      }
    } else if (finding.where === 'face' || finding.where === 'pair') {
      const faces = finding.where === 'pair' ? location : [location];
      faces.forEach((face, i) => {
        const mesh = polygons(view.point, [located(face)], overlayMaterial(i === 0 ? colour : SECOND_FACE_COLOUR, 0.8));
        if (mesh.geometry.attributes.position.count > 0) objects.push(mesh);
      });
      points = faces.flatMap((face) => located(face).map((v) => view.point(v)).filter(Boolean));
    } else if (finding.where === 'shell' && view.faceShells) {
      const material = overlayMaterial(colour, 0.45);
      objects.push(polygons(view.corner, shellTriangles(view, location), material));
    }
    const sceneToFile = (p) => p.map((x, axis) => x + origin[axis]);
    state.drawn.push({ key: finding.key, index: state.drawn.filter((d) => d.key === finding.key).length, what: finding.where, location, points: points.map(sceneToFile) });
    return objects.map((object) => onTop(object, 10));
  }

  function checkStatus(report) {
    if (report.error) return el('div', { class: 'status bad' }, 'Cannot be read: ' + report.error.message);
    if (report.valid) return el('div', { class: 'status good' }, 'A valid closed solid');
    return el('div', { class: 'status bad' }, el('b', {}, 'Not a valid solid: ' + report.category), ' — ' + report.message);
  }

  function answerText(answer) {
    if (!answer) return null;
    if (answer.option) return answer.option + ' would give an answer (' + answer.mode + ')';
    return answer.mode ? 'Answered as ' + answer.mode : 'No mode gives an answer';
  }

  function showCheck(report, mesh) {
    const details = document.getElementById('details');
    const view = mesh ? buildMesh(mesh, {}) : null;
    if (view) showMesh(view);
    const radius = view ? view.geometry.boundingSphere.radius : 1;
    const summary = [checkStatus(report)];
    if (!report.error) {
      summary.push(
        el(
          'p',
          {},
          plural(report.faces, 'face') + ', ' + plural(report.used_vertices, 'vertex', 'vertices') + ' used' +
            ', ' + plural(report.edges, 'edge') + ', ' + plural(report.shells, 'shell'),
          el('br'),
          answerText(report.answer),
          el('br'),
          'signed volume ' + number(report.signed_volume) + ', max non-planarity ' + number(report.max_non_planarity)
        )
      );
    }
    document.getElementById('summary').replaceChildren(...summary);
    if (report.error) return;

    const rows = [];
    const legend = [];
    for (const finding of findingsOf(report)) {
      const [label, colour] = CHECK_KINDS[finding.key] || [finding.key.replace(/_/g, ' '), '#555555'];
      const kindRow = el(
        'tr',
        { class: 'kind-row' + (finding.count === 0 ? ' zero' : ''), dataset: { key: finding.key, count: finding.count } },
        el('td', {}, el('span', { class: 'swatch', style: 'background:' + colour }), label),
        numberCell(finding.count),
        el('td', {}, finding.count === 0 ? '' : finding.locations.length < finding.count ? 'the first ' + finding.locations.length + ':' : '')
      );
      rows.push(kindRow);
      const all = [];
      finding.locations.forEach((location) => {
        const objects = view ? drawLocation(view, finding, location, 0.006 * radius) : [];
        objects.forEach((object) => viewer.content.add(object));
        all.push(...objects);
        const row = el(
          'tr',
          { class: 'location-row', dataset: { key: finding.key, location: JSON.stringify(location) } },
          el('td', {}),
          el('td', {}),
          el('td', { class: 'mono' }, locationText(finding, location, view))
        );
        rows.push(row);
        makeSelectable(row, objects, objects.length ? sphereOf(objects, 0.12 * radius) : null);
      });
      if (finding.count > finding.locations.length) {
        rows.push(el('tr', { class: 'more' }, el('td'), el('td'), el('td', {}, '… and ' + (finding.count - finding.locations.length) + ' more (not located by the library)')));
      }
      if (finding.count > 0) {
        makeSelectable(kindRow, all, all.length ? sphereOf(all, 0.12 * radius) : null);
        if (all.length) legend.push([colour, label]);
      }
    }
    const parts = [el('h2', {}, 'Findings'), table(['Finding', 'Count', 'Where'], rows)];
    parts[1].id = 'findings';

    if (report.shell_list && report.shell_list.length > 1) {
      const shellRows = report.shell_list.map((shell, index) => {
        const row = el(
          'tr',
          { class: 'shell-row', dataset: { shell: index } },
          el('td', {}, String(index)),
          el('td', {}, shell.kind),
          numberCell(shell.faces),
          numberCell(shell.first_face),
          numberCell(shell.signed_volume)
        );
        const objects = view && view.faceShells ? [polygons(view.corner, shellTriangles(view, index), overlayMaterial('#1f6fd1', 0.35))] : [];
        objects.forEach((object) => {
          object.visible = false; // shown when its row is selected
          viewer.content.add(object);
        });
        const entry = makeSelectable(row, objects, objects.length ? sphereOf(objects, 0.05 * radius) : null);
        row.addEventListener('click', () => objects.forEach((object) => (object.visible = row.classList.contains('selected'))));
        return entry.row;
      });
      parts.push(el('h2', {}, 'Shells'), table(['Shell', 'Kind', 'Faces', 'First face', 'Signed volume'], shellRows));
    }
    details.replaceChildren(...parts);

    if (view && report.answer && report.answer.mode === 'hull' && !report.answer.option) {
      const hull = hullObject(view);
      viewer.content.add(hull);
      toggle('Hull (the answer)', hull, true);
      legend.push(['#2e9e5b', 'convex hull (the answer)']);
    }
    legend.push(['#' + BACK_COLOUR.toString(16), 'inside of the surface']);
    setLegend(legend);
    setNotes(decimationNote(mesh));
    const found = selectable.flatMap((entry) => (entry.row.classList.contains('kind-row') ? entry.objects : []));
    if (view && found.length) viewer.homeDirection = lookTowards(sphereOf(found, 0).center, view.geometry.boundingSphere.center);
  }

  // ---- equivalent inertia boxes -------------------------------------------

  // The uniform box with the same mass and principal moments: side i is
  // sqrt(6/m (Ij + Ik - Ii)) (docs/html-report.md). A negative radicand
  // (rounding of a flat body's moments, or moments that break the triangle
  // inequality) is clamped to 0 and said.
  function equivalentBox(mass, moments) {
    const sides = [0, 1, 2].map((i) => (6 / mass) * (moments[(i + 1) % 3] + moments[(i + 2) % 3] - moments[i]));
    return { sides: sides.map((s) => Math.sqrt(Math.max(0, s))), clamped: sides.map((s) => s < 0) };
  }

  // The principal moments (ascending) and axes (columns) of a symmetric
  // tensor given as rows: Jacobi rotations, exact enough for a drawing.
  function principalOf(rows) {
    const a = rows.map((row) => row.slice());
    const v = [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
    for (let sweep = 0; sweep < 50; sweep++) {
      const off = Math.abs(a[0][1]) + Math.abs(a[0][2]) + Math.abs(a[1][2]);
      if (off <= 1e-15 * (Math.abs(a[0][0]) + Math.abs(a[1][1]) + Math.abs(a[2][2]))) break;
      for (const [p, q] of [[0, 1], [0, 2], [1, 2]]) {
        if (a[p][q] === 0) continue;
        const theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
        const t = Math.sign(theta || 1) / (Math.abs(theta) + Math.sqrt(theta * theta + 1));
        const c = 1 / Math.sqrt(t * t + 1);
        const s = t * c;
        for (let k = 0; k < 3; k++) {
          const akp = a[k][p];
          const akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (let k = 0; k < 3; k++) {
          const apk = a[p][k];
          const aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for (let k = 0; k < 3; k++) {
          const vkp = v[k][p];
          const vkq = v[k][q];
          v[k][p] = c * vkp - s * vkq;
          v[k][q] = s * vkp + c * vkq;
        }
      }
    }
    const order = [0, 1, 2].sort((i, j) => a[i][i] - a[j][j]);
    return { moments: order.map((i) => a[i][i]), axes: order.map((i) => [v[0][i], v[1][i], v[2][i]]) };
  }

  // The box drawn: its edges, faint faces, at center (file coordinates)
  // with its sides along axes; recorded in state.boxes.
  function boxObject(box, center, axes, colour, record) {
    const geometry = new THREE.BoxBufferGeometry(...box.sides.map((s) => Math.max(s, 1e-12)));
    const group = new THREE.Group();
    group.add(new THREE.LineSegments(new THREE.EdgesGeometry(geometry), new THREE.LineBasicMaterial({ color: colour, depthTest: false, transparent: true })));
    group.add(new THREE.Mesh(geometry, new THREE.MeshBasicMaterial({ color: colour, transparent: true, opacity: 0.12, depthWrite: false })));
    const [x, y, z] = axes.map((axis) => new THREE.Vector3(...axis));
    group.quaternion.setFromRotationMatrix(new THREE.Matrix4().makeBasis(x, y, z.clone().crossVectors(x, y)));
    group.position.copy(vector(center));
    group.children[0].renderOrder = 5;
    state.boxes.push(Object.assign({ sides: box.sides, clamped: box.clamped, center, axes }, record));
    return group;
  }

  function centreMarker(center, radius, colour) {
    const group = new THREE.Group();
    const material = overlayMaterial(colour);
    group.add(dot(vector(center), radius, material));
    return onTop(group, 11);
  }

  function axesObject(center, axes, lengths) {
    const group = new THREE.Group();
    ['#d62728', '#2ca02c', '#1f77b4'].forEach((colour, i) => {
      const arrow = new THREE.ArrowHelper(new THREE.Vector3(...axes[i]), vector(center), lengths[i], colour, 0.15 * lengths[i], 0.06 * lengths[i]);
      group.add(onTop(arrow, 12));
    });
    return group;
  }

  // ---- polymass FILE (mass properties) --------------------------------------

  const tensorRows = (rows) => rows.map((row) => el('div', { class: 'mono' }, vectorText(row)));

  function propertiesTable(solid, box, unit) {
    const length = unit || 'file units';
    const rows = [
      ['mass', number(solid.mass)],
      ['volume', number(solid.volume) + ' (' + length + ')³'],
      ['density', number(solid.density)],
      ['centre of mass', vectorText(solid.center_of_mass)],
      ['inertia about the centre of mass', tensorRows(solid.inertia)],
      ['principal moments', vectorText(solid.principal_moments)],
      ['principal axes (columns: 1, 2, 3)', tensorRows(solid.principal_axes)],
      ['equivalent inertia box, sides', vectorText(box.sides) + (box.clamped.some(Boolean) ? ' (a side clamped to 0: its moments break the box’s triangle inequality by rounding)' : '')],
      ['surface area', number(solid.surface_area)],
      ['warnings', solid.warnings.length ? solid.warnings.join(', ') : 'none'],
      ['answered as', solid.provenance.mode],
    ];
    return table(['Quantity', 'Value'], rows.map(([name, value]) => el('tr', {}, el('td', {}, name), el('td', {}, value))));
  }

  function showProperties(file, mesh) {
    const summary = document.getElementById('summary');
    const details = document.getElementById('details');
    const view = mesh ? buildMesh(mesh, { opacity: file.error ? 1 : 0.4 }) : null;
    if (view) showMesh(view);
    setNotes(decimationNote(mesh));
    if (file.error) {
      // Unreadable, or not a valid solid: the mesh (when read) and why.
      summary.replaceChildren(el('div', { class: 'status bad' }, file.error.category + ': ' + file.error.message));
      details.replaceChildren();
      return;
    }
    const radius = view ? view.geometry.boundingSphere.radius : 1;
    summary.replaceChildren(
      el('div', { class: 'status good' }, plural(file.faces, 'face') + ', mass ' + number(file.mass) + ', volume ' + number(file.volume)),
      ...(file.notes ? [el('p', {}, file.notes.join('; '))] : [])
    );
    const legend = [];
    const parts = [];
    if (file.parts) {
      parts.push(
        el('h2', {}, 'Parts'),
        table(['Part', 'Faces', 'Mass', 'Centre of mass'], file.parts.map((part) =>
          el('tr', {}, el('td', {}, part.name), numberCell(part.faces), numberCell(part.mass), el('td', { class: 'mono' }, part.center_of_mass ? vectorText(part.center_of_mass) : (part.error ? part.error.message : '—'))))
        )
      );
    }
    const box = equivalentBox(file.mass, file.principal_moments);
    viewer.content.add(boxObject(box, file.center_of_mass, file.principal_axes, '#1f6fd1', { which: 'computed' }));
    viewer.content.add(centreMarker(file.center_of_mass, 0.02 * radius, '#111111'));
    const lengths = box.sides.map((s) => Math.max(0.75 * s, 0.25 * radius));
    viewer.content.add(axesObject(file.center_of_mass, file.principal_axes, lengths));
    legend.push(['#111111', 'centre of mass'], ['#d62728', 'axis 1'], ['#2ca02c', 'axis 2'], ['#1f77b4', 'axis 3'], ['#1f6fd1', 'equivalent inertia box']);
    const provenance = file.provenance;
    if (view && provenance.mode === 'hull') {
      const hull = hullObject(view);
      viewer.content.add(hull);
      toggle('Hull (the answer)', hull, true);
      legend.push(['#2e9e5b', 'convex hull (the answer)']);
    }
    if (view && provenance.mode === 'repaired' && provenance.repairs.holes) {
      // The library locates each capped hole by its lowest vertex.
      const material = overlayMaterial('#e6194b');
      for (const [v] of provenance.repairs.holes.first) {
        const p = view.point(v);
        if (p) viewer.content.add(dot(new THREE.Vector3(...p), 0.025 * radius, material));
      }
      legend.push(['#e6194b', 'capped hole (its lowest vertex)']);
    }
    details.replaceChildren(el('h2', {}, 'Mass properties'), propertiesTable(file, box, file.length_unit), ...parts);
    setLegend(legend);
  }


  // ---- polymass audit -------------------------------------------------------

  const SEVERITY_RANK = { error: 2, warning: 1, info: 0 };
  const DECLARED_COLOUR = '#e8590c';
  const COMPUTED_COLOUR = '#1f6fd1';
  const LINK_COLOURS = [0xb4c0cc, 0xc9bfa8, 0xa8c3b5, 0xc3b0c9, 0xb0bdd8, 0xd1b8b0];

  const worstSeverity = (link) => Math.max(-1, ...link.findings.map((f) => SEVERITY_RANK[f.severity]));

  // A 4x4 matrix from a pose ({rotation: rows, position}).
  function poseMatrix(pose) {
    const r = pose.rotation;
    const p = pose.position;
    return new THREE.Matrix4().set(r[0][0], r[0][1], r[0][2], p[0], r[1][0], r[1][1], r[1][2], p[1], r[2][0], r[2][1], r[2][2], p[2], 0, 0, 0, 1);
  }
  const applyPose = (pose, point) => new THREE.Vector3(...point).applyMatrix4(poseMatrix(pose)).toArray();
  const rotate = (pose, axis) => new THREE.Vector3(...axis).applyMatrix3(new THREE.Matrix3().setFromMatrix4(poseMatrix(pose))).toArray();

  // A shape of the audit (audit/description.hpp) as three.js geometries
  // (one, or a capsule's three), about its centre, its axis along z.
  function shapeGeometry(geometry) {
    const [a, b, c] = geometry.size;
    const upright = (g) => g.rotateX(Math.PI / 2);
    switch (geometry.shape) {
      case 'box':
        return new THREE.BoxBufferGeometry(a, b, c);
      case 'cylinder':
        return upright(new THREE.CylinderBufferGeometry(a, a, b, 32));
      case 'sphere':
        return new THREE.SphereBufferGeometry(a, 32, 16);
      case 'ellipsoid':
        return new THREE.SphereBufferGeometry(1, 32, 16).scale(a, b, c);
      case 'capsule': {
        // The cylinder with a half sphere on each end: r111 has no capsule.
        const sphere = new THREE.SphereBufferGeometry(a, 32, 16);
        return [upright(new THREE.CylinderBufferGeometry(a, a, b, 32, 1, true)), sphere.clone().translate(0, 0, b / 2), sphere.translate(0, 0, -b / 2)];
      }
      default:
        return null;
    }
  }

  function linkGeometryObjects(link, colour) {
    const objects = [];
    const notes = [];
    for (const geometry of link.geometries) {
      let object = null;
      if (geometry.shape === 'mesh') {
        if (!geometry.mesh || geometry.mesh.error) {
          notes.push(geometry.uri + ': ' + (geometry.mesh ? geometry.mesh.error : 'not drawn'));
          continue;
        }
        const view = buildMesh(geometry.mesh, { colour });
        showMesh(view);
        object = new THREE.Group();
        object.add(view.solid, view.wireframe);
        object.scale.set(...geometry.scale);
        notes.push(...decimationNote(geometry.mesh).map((note) => geometry.uri + ': ' + note));
      } else {
        const shapes = shapeGeometry(geometry);
        object = new THREE.Group();
        for (const shape of [].concat(shapes)) {
          object.add(new THREE.Mesh(shape, new THREE.MeshPhongMaterial({ color: colour, flatShading: false })));
        }
      }
      const placed = new THREE.Group();
      placed.matrixAutoUpdate = false;
      placed.matrix.copy(poseMatrix(link.frame || IDENTITY_POSE).multiply(poseMatrix(geometry.pose)));
      placed.add(object);
      objects.push(placed);
    }
    return { objects, notes };
  }
  const IDENTITY_POSE = { rotation: [[1, 0, 0], [0, 1, 0], [0, 0, 1]], position: [0, 0, 0] };

  // A link's declared or computed inertial drawn in the world: its centre
  // of mass and equivalent inertia box.
  function inertialObjects(name, which, inertial, frame, colour, size, notes) {
    const { moments, axes } = principalOf(inertial.inertia);
    const box = equivalentBox(inertial.mass, moments);
    if (box.clamped.some(Boolean)) {
      notes.push(name + ': the ' + which + ' inertia box has a side clamped to 0: its principal moments break the triangle inequality (Iⱼ + Iₖ < Iᵢ)');
    }
    const center = applyPose(frame, inertial.center_of_mass);
    const group = new THREE.Group();
    group.add(boxObject(box, center, axes.map((axis) => rotate(frame, axis)), colour, { link: name, which, moments }));
    group.add(centreMarker(center, size, colour));
    return group;
  }

  function linkRow(link) {
    const findings = [...link.findings].sort((a, b) => SEVERITY_RANK[b.severity] - SEVERITY_RANK[a.severity]);
    const declared = link.declared;
    const computed = link.computed;
    return el(
      'tr',
      { class: 'link-row', dataset: { link: link.name } },
      el('td', {}, el('b', {}, link.name), el('br'), el('span', { class: 'mono' }, link.geometry)),
      el('td', { class: 'number' }, declared ? number(declared.mass) : '—', el('br'), computed ? number(computed.mass) : '—'),
      el(
        'td',
        {},
        findings.length
          ? findings.map((finding) => el('div', { class: 'finding', dataset: { kind: finding.kind, severity: finding.severity } }, el('span', { class: 'severity-' + finding.severity }, finding.severity), ' ', el('code', {}, finding.kind), ': ', finding.message))
          : el('span', { class: 'severity-info' }, 'no finding')
      )
    );
  }

  function showAudit(file, index) {
    const summary = document.getElementById('summary');
    const details = document.getElementById('details');
    if (file.error) {
      summary.replaceChildren(el('div', { class: 'status bad' }, file.error));
      details.replaceChildren();
      return;
    }
    const robot = data.robots[index];
    const counts = { error: 0, warning: 0, info: 0 };
    file.links.forEach((link) => link.findings.forEach((finding) => counts[finding.severity]++));
    summary.replaceChildren(
      el('div', { class: 'status ' + (counts.error ? 'bad' : counts.warning ? 'warning' : 'good') }, file.format.toUpperCase() + ', ' + plural(file.links.length, 'link') + ': ' + plural(counts.error, 'error') + ', ' + plural(counts.warning, 'warning') + ', ' + counts.info + ' info'),
      el('p', {}, 'Zero pose (every joint at 0). Declared inertials in ', el('b', { style: 'color:' + DECLARED_COLOUR }, 'orange'), ', computed from the geometry in ', el('b', { style: 'color:' + COMPUTED_COLOUR }, 'blue'), ': each a centre of mass and its equivalent inertia box (the uniform box with the same mass and principal moments). Where they differ, the declared inertial is wrong or the geometry is not the link.')
    );
    const notes = [];
    const order = file.links.map((link, i) => i).sort((a, b) => worstSeverity(file.links[b]) - worstSeverity(file.links[a]) || a - b);
    // Sizes of the markers: a share of the robot's extent, known once its
    // links are placed.
    const placed = [];
    file.links.forEach((link, i) => {
      const drawn = robot ? robot.links[i] : { frame: null, geometries: [] };
      if (!drawn.frame) notes.push(link.name + ': its pose is not known; drawn at the origin');
      const { objects, notes: geometryNotes } = linkGeometryObjects(drawn, LINK_COLOURS[i % LINK_COLOURS.length]);
      notes.push(...geometryNotes.map((note) => link.name + ': ' + note));
      objects.forEach((object) => viewer.content.add(object));
      placed[i] = { link, drawn, objects };
    });
    const extent = new THREE.Box3().setFromObject(viewer.content).getBoundingSphere(new THREE.Sphere()).radius || 1;
    const rows = [];
    for (const i of order) {
      const { link, drawn, objects } = placed[i];
      const frame = drawn.frame || IDENTITY_POSE;
      const inertials = [];
      if (link.declared && link.declared.mass > 0) inertials.push(inertialObjects(link.name, 'declared', link.declared, frame, DECLARED_COLOUR, 0.012 * extent, notes));
      if (link.computed) inertials.push(inertialObjects(link.name, 'computed', link.computed, frame, COMPUTED_COLOUR, 0.012 * extent, notes));
      inertials.forEach((object) => viewer.content.add(object));
      const row = linkRow(link);
      const all = [...objects, ...inertials];
      makeSelectable(row, all, all.length ? sphereOf(all, 0.05 * extent) : null);
      rows.push(row);
    }
    const linkTable = table(['Link (geometry)', 'Mass: declared, computed', 'Findings (most severe first)'], rows);
    linkTable.id = 'links';
    details.replaceChildren(el('h2', {}, 'Links, the most severe findings first'), linkTable);
    setLegend([[DECLARED_COLOUR, 'declared: centre of mass, inertia box'], [COMPUTED_COLOUR, 'computed from the geometry']]);
    setNotes(notes);
  }

  // ---- the page -----------------------------------------------------------

  function fileList() {
    if (data.kind === 'audit') return data.report.files || [data.report];
    if (data.kind === 'properties') return data.report.files || [data.report];
    return Array.isArray(data.report) ? data.report : [data.report];
  }

  function show(index) {
    state.file = index;
    state.drawn = [];
    state.boxes = [];
    selectable = [];
    meshViews.length = 0;
    viewer.clear();
    document.getElementById('toolbar-extra').replaceChildren();
    viewer.homeDirection = DEFAULT_DIRECTION.clone();
    const files = fileList();
    const file = files[index];
    const mesh = data.meshes ? data.meshes[index] : null;
    origin = mesh ? mesh.origin : [0, 0, 0];
    document.getElementById('title').textContent = file.file;
    if (data.kind === 'check') showCheck(file, mesh);
    else if (data.kind === 'properties') showProperties(file, mesh);
    else showAudit(file, index);
    const box = new THREE.Box3().setFromObject(viewer.content);
    viewer.home = box.isEmpty() ? new THREE.Sphere(new THREE.Vector3(), 1) : box.getBoundingSphere(new THREE.Sphere());
    viewer.resize();
    viewer.frame(viewer.home, true);
  }

  const KIND_TITLES = { check: 'polymass check', properties: 'polymass: mass properties', audit: 'polymass audit' };
  document.title = KIND_TITLES[data.kind] + ' — ' + fileList().map((file) => file.file.split('/').pop()).join(', ');
  document.getElementById('subtitle').textContent = KIND_TITLES[data.kind];
  document.getElementById('generator').textContent = 'Written by ' + data.generator + '.';
  const files = fileList();
  if (files.length > 1) {
    const chooser = document.getElementById('file-select');
    chooser.hidden = false;
    files.forEach((file, index) => chooser.append(el('option', { value: index }, file.file)));
    chooser.addEventListener('change', () => show(Number(chooser.value)));
  }
  state.show = show;
  show(0);
  state.ready = true;
})();
