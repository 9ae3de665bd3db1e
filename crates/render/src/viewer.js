// dualex mesh viewer: a small WebGL 1 viewer, no dependencies.
// Reads the mesh from <script id="mesh" type="application/json">:
//   { "title": str, "positions": [x,y,z, ...], "quads": [a,b,c,d, ...],
//     "valence": [code per vertex: 3, 4, 5, 0 = other, -1 = not marked],
//     hex meshes only: "hexes": [8 ids each], "hex_faces": [[4 corners] x 6],
//     optional: "quality": [one value per quad, or per hex], "quality_note": str,
//     hex meshes with quality: "quad_hex": [the hex of each boundary quad] }
// (for a hex mesh, "quads" is its boundary, on the same vertex ids).
// With quality, a button (or key q, or #quality in the URL) switches from
// the valence dots to the elements coloured by quality: <= 0 (inverted)
// red, then a ramp: orange (0), yellow (0.5), green (0.8), blue (1).
// Hex meshes get a cut plane: an axis and a slider; the hexes whose
// centroid lies beyond the plane are hidden and the faces of the others
// that become exposed are drawn. `#cut=z:0.5` in the URL sets it at load.
// Small windows start with the panel collapsed (click the title).
// Draws the quads flat-shaded (two-sided Lambert), their edges (as thin
// screen-space quads: GL lines go missing under software rendering), and the
// vertices as dots in their valence colour. Drag: orbit; wheel: zoom;
// right drag or shift drag: pan; double click: reset; keys e / d: edges
// (shown by default when at least 4 px long) / dots on or off.
"use strict";
(function () {
  var COLOURS = { 3: [0x1f, 0x66, 0xd1], 4: [0x4d, 0x4d, 0x4d], 5: [0xd6, 0x27, 0x28], 0: [0x2c, 0xa0, 0x2c] };
  var GREY = [0.863, 0.863, 0.863], INVERTED = [0xd6 / 255, 0x27 / 255, 0x28 / 255];
  var RAMP = [[0, [0xf0, 0x9a, 0x1a]], [0.5, [0xf2, 0xd8, 0x4a]], [0.8, [0x9c, 0xcf, 0x6e]], [1, [0x8f, 0xbc, 0xe6]]];
  // the colour (0..1 floats) of a quality value
  function qualityColour(v) {
    if (!(v > 0)) return INVERTED;
    for (var i = 1; i < RAMP.length; i++) {
      if (v <= RAMP[i][0] || i === RAMP.length - 1) {
        var t = Math.min(1, (v - RAMP[i - 1][0]) / (RAMP[i][0] - RAMP[i - 1][0]));
        return [0, 1, 2].map(function (k) {
          return ((1 - t) * RAMP[i - 1][1][k] + t * RAMP[i][1][k]) / 255;
        });
      }
    }
    return GREY;
  }
  var mesh = JSON.parse(document.getElementById("mesh").textContent);
  var canvas = document.getElementById("view");
  var status = document.getElementById("status");
  var gl = canvas.getContext("webgl", { antialias: true, preserveDrawingBuffer: true }) ||
    canvas.getContext("experimental-webgl", { preserveDrawingBuffer: true });
  if (!gl) {
    status.textContent = "WebGL is not available in this browser.";
    return;
  }

  // ---- geometry: centre and radius of the bounding box --------------------
  var P = mesh.positions, Q = mesh.quads, V = mesh.valence;
  var lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (var i = 0; i < P.length; i += 3) {
    for (var k = 0; k < 3; k++) {
      lo[k] = Math.min(lo[k], P[i + k]);
      hi[k] = Math.max(hi[k], P[i + k]);
    }
  }
  var centre = [0, 1, 2].map(function (k) { return P.length ? 0.5 * (lo[k] + hi[k]) : 0; });
  var radius = 0;
  for (var k2 = 0; k2 < 3; k2++) radius += P.length ? Math.pow(hi[k2] - lo[k2], 2) : 0;
  radius = Math.sqrt(radius) * 0.5 || 1;
  function pos(v, k) { return (P[3 * v + k] - centre[k]) / radius; }

  // hex meshes: the hexes (8 ids each) and the 6 faces of a hex (outward,
  // corner numbers); the cut keeps the hexes whose centroid is at most
  // `cut.at` (fraction of the box) along `cut.axis` and draws the faces
  // used by one kept hex
  var H = mesh.hexes || null, HF = mesh.hex_faces || [];
  var QV = mesh.quality || null, QH = mesh.quad_hex || null;
  var byQuality = !!QV && /(^#|[#&])quality/.test(window.location.hash);
  var nh = H ? H.length / 8 : 0;
  var cut = { axis: 2, at: 1 };
  var hashCut = /cut=([xyz]):([0-9.]+)/.exec(window.location.hash);
  if (H && hashCut) cut = { axis: "xyz".indexOf(hashCut[1]), at: parseFloat(hashCut[2]) };
  // the quads to draw and the element (quad or hex) of each
  function cutQuads() {
    if (!H || cut.at >= 1) return { quads: Q, element: QH };
    var limit = lo[cut.axis] + cut.at * (hi[cut.axis] - lo[cut.axis]) + 1e-9 * radius;
    var faces = {}, order = [];
    for (var h = 0; h < nh; h++) {
      var sum = 0;
      for (var i = 0; i < 8; i++) sum += P[3 * H[8 * h + i] + cut.axis];
      if (sum / 8 > limit) continue;
      for (var fi = 0; fi < HF.length; fi++) {
        var fc = HF[fi].map(function (k) { return H[8 * h + k]; });
        var key = fc.slice().sort(function (a, b) { return a - b; }).join(",");
        if (faces[key]) faces[key].n++;
        else { faces[key] = { n: 1, c: fc, h: h }; order.push(key); }
      }
    }
    var out = [], element = [];
    order.forEach(function (key) {
      if (faces[key].n === 1) { out.push.apply(out, faces[key].c); element.push(faces[key].h); }
    });
    return { quads: out, element: element };
  }

  // faces: two triangles per quad, flat normal (Newell) and colour per
  // quad (grey, or by the quality of its element: `element[q]`, or q)
  var faceData, edgeData, dotData, nRegular, nq, meanEdge = 1, counts = { 3: 0, 4: 0, 5: 0, 0: 0 };
  function build(drawn) {
  var Q = drawn.quads, element = drawn.element;
  nq = Q.length / 4;
  faceData = new Float32Array(nq * 6 * 9);
  // edges as thin screen-space quads (GL lines go missing under some
  // software renderers): 6 vertices of (a xyz, b xyz, end, side) each
  edgeData = new Float32Array(nq * 4 * 6 * 8);
  var f = 0, e = 0, edgeSum = 0, used = new Uint8Array(V.length);
  for (var q = 0; q < nq; q++) {
    var c = [Q[4 * q], Q[4 * q + 1], Q[4 * q + 2], Q[4 * q + 3]];
    var n = [0, 0, 0];
    for (var j = 0; j < 4; j++) {
      var a = c[j], b = c[(j + 1) % 4];
      used[a] = 1;
      n[0] += (pos(a, 1) - pos(b, 1)) * (pos(a, 2) + pos(b, 2));
      n[1] += (pos(a, 2) - pos(b, 2)) * (pos(a, 0) + pos(b, 0));
      n[2] += (pos(a, 0) - pos(b, 0)) * (pos(a, 1) + pos(b, 1));
    }
    var tri = [c[0], c[1], c[2], c[0], c[2], c[3]];
    var colour = byQuality ? qualityColour(QV[element ? element[q] : q]) : GREY;
    for (var t = 0; t < 6; t++) {
      for (var k3 = 0; k3 < 3; k3++) faceData[f++] = pos(tri[t], k3);
      for (var k4 = 0; k4 < 3; k4++) faceData[f++] = n[k4];
      for (var k7 = 0; k7 < 3; k7++) faceData[f++] = colour[k7];
    }
    for (var j2 = 0; j2 < 4; j2++) {
      var ends = [c[j2], c[(j2 + 1) % 4]];
      edgeSum += Math.sqrt([0, 1, 2].reduce(function (acc, k) {
        return acc + Math.pow(pos(ends[0], k) - pos(ends[1], k), 2);
      }, 0));
      var corners = [[0, -1], [1, -1], [1, 1], [0, -1], [1, 1], [0, 1]];
      for (var m = 0; m < 6; m++) {
        for (var k5 = 0; k5 < 3; k5++) edgeData[e++] = pos(ends[0], k5);
        for (var k6 = 0; k6 < 3; k6++) edgeData[e++] = pos(ends[1], k6);
        edgeData[e++] = corners[m][0]; edgeData[e++] = corners[m][1];
      }
    }
  }
  // dots: every marked vertex on a drawn face, regular ones first (drawn
  // only when the quads are large enough on screen), irregular ones after
  // (on top); the legend counts the whole mesh (first build)
  var regular = [], irregular = [], first = !faceBuf;
  for (var v = 0; v < V.length; v++) {
    var code = V[v];
    if (!(code in COLOURS)) continue;
    if (first) counts[code]++;
    if (!used[v]) continue;
    var col = COLOURS[code];
    (code === 4 ? regular : irregular).push(pos(v, 0), pos(v, 1), pos(v, 2),
      col[0] / 255, col[1] / 255, col[2] / 255, code === 4 ? 0.45 : 1);
  }
  nRegular = regular.length / 7;
  dotData = new Float32Array(regular.concat(irregular));
  // mean edge length (model units scaled to radius 1) of the whole mesh
  if (first) meanEdge = nq ? edgeSum / (4 * nq) : 1;
  }
  var faceBuf = null, edgeBuf, dotBuf;
  // null: automatic (edges when at least 4 px long); true/false: forced
  var showEdges = null, showDots = true;

  // ---- shaders ---------------------------------------------------------------
  var HEAD = "precision mediump float;\n" +
    "uniform mat3 rot; uniform vec2 scale; uniform vec2 pan;\n" +
    "vec4 place(vec3 p, float lift) {\n" +
    "  vec3 q = rot * p;\n" +
    "  return vec4(q.xy * scale + pan, -0.5 * q.z - lift, 1.0);\n}\n";
  var FACE_VS = HEAD + "attribute vec3 p; attribute vec3 n; attribute vec3 c;\n" +
    "varying vec3 vn; varying vec3 vc;\n" +
    "void main() { vn = rot * n; vc = c; gl_Position = place(p, 0.0); }\n";
  var FACE_FS = "precision mediump float; varying vec3 vn; varying vec3 vc;\n" +
    "void main() {\n" +
    "  vec3 l = normalize(vec3(-0.3, 0.45, 1.0));\n" +
    "  float len = length(vn);\n" +
    "  float d = len > 0.0 ? abs(dot(vn / len, l)) : 1.0;\n" +
    "  gl_FragColor = vec4(vc * (0.35 + 0.65 * d), 1.0);\n}\n";
  var LINE_VS = HEAD + "attribute vec3 a; attribute vec3 b; attribute vec2 es;\n" +
    "uniform vec2 px; uniform float width;\n" +
    "void main() {\n" +
    "  vec4 pa = place(a, 0.0005), pb = place(b, 0.0005);\n" +
    "  vec2 d = (pb.xy - pa.xy) / px;\n" +
    "  float len = length(d);\n" +
    "  vec2 n = len > 0.0 ? vec2(-d.y, d.x) / len : vec2(0.0, 1.0);\n" +
    "  vec4 p = es.x > 0.5 ? pb : pa;\n" +
    "  p.xy += n * es.y * 0.5 * width * px;\n" +
    "  gl_Position = p;\n}\n";
  var LINE_FS = "precision mediump float;\nvoid main() { gl_FragColor = vec4(0.19, 0.19, 0.19, 1.0); }\n";
  var DOT_VS = HEAD + "attribute vec3 p; attribute vec4 c; uniform float size; varying vec3 vc;\n" +
    "void main() { vc = c.rgb; gl_PointSize = size * c.a; gl_Position = place(p, 0.004); }\n";
  var DOT_FS = "precision mediump float; varying vec3 vc;\n" +
    "void main() {\n" +
    "  vec2 d = gl_PointCoord - vec2(0.5);\n" +
    "  if (dot(d, d) > 0.25) discard;\n" +
    "  gl_FragColor = vec4(vc, 1.0);\n}\n";

  function shader(type, src) {
    var s = gl.createShader(type);
    gl.shaderSource(s, src);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s));
    return s;
  }
  function program(vs, fs) {
    var p = gl.createProgram();
    gl.attachShader(p, shader(gl.VERTEX_SHADER, vs));
    gl.attachShader(p, shader(gl.FRAGMENT_SHADER, fs));
    gl.linkProgram(p);
    if (!gl.getProgramParameter(p, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(p));
    return p;
  }
  function buffer(data) {
    var b = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, b);
    gl.bufferData(gl.ARRAY_BUFFER, data, gl.STATIC_DRAW);
    return b;
  }
  var faceProg = program(FACE_VS, FACE_FS);
  var lineProg = program(LINE_VS, LINE_FS);
  var dotProg = program(DOT_VS, DOT_FS);
  function upload() {
    [faceBuf, edgeBuf, dotBuf].forEach(function (b) { if (b) gl.deleteBuffer(b); });
    faceBuf = buffer(faceData); edgeBuf = buffer(edgeData); dotBuf = buffer(dotData);
  }
  build({ quads: Q, element: QH });
  upload();
  if (H && cut.at < 1) { build(cutQuads()); upload(); }

  // attribute `name` of `prog`: `size` floats at `offset` in a `stride`-float record
  function attrib(prog, name, size, stride, offset) {
    var loc = gl.getAttribLocation(prog, name);
    if (loc < 0) return;
    gl.enableVertexAttribArray(loc);
    gl.vertexAttribPointer(loc, size, gl.FLOAT, false, stride * 4, offset * 4);
  }
  function disableAll() {
    var max = gl.getParameter(gl.MAX_VERTEX_ATTRIBS);
    for (var i = 0; i < max; i++) gl.disableVertexAttribArray(i);
  }

  // ---- camera ----------------------------------------------------------------
  var cam = {};
  // the mesh is fitted into the part of the window right of the panel
  // (when the panel is open and takes less than 45 % of the width)
  function reset() {
    cam.yaw = -0.52; cam.pitch = 0.35;
    var panel = document.getElementById("panel");
    var w = canvas.clientWidth || 1, h = canvas.clientHeight || 1;
    var pw = panel && panel.open ? panel.offsetWidth + 16 : 0;
    if (pw > 0.45 * w) pw = 0;
    cam.zoom = 0.95 * Math.min(1, Math.min(w - pw, h) / Math.min(w, h));
    cam.pan = [pw / w, 0];
  }
  reset();
  function rotation() {
    var cy = Math.cos(cam.yaw), sy = Math.sin(cam.yaw), cp = Math.cos(cam.pitch), sp = Math.sin(cam.pitch);
    // R = Rx(pitch) * Ry(yaw), column-major for WebGL
    return new Float32Array([cy, sp * sy, -cp * sy, 0, cp, sp, sy, -sp * cy, cp * cy]);
  }
  function uniforms(prog) {
    var w = canvas.width, h = canvas.height, s = Math.min(w, h);
    gl.uniformMatrix3fv(gl.getUniformLocation(prog, "rot"), false, rotation());
    gl.uniform2f(gl.getUniformLocation(prog, "scale"), cam.zoom * s / w, cam.zoom * s / h);
    gl.uniform2f(gl.getUniformLocation(prog, "pan"), cam.pan[0], cam.pan[1]);
  }

  function draw() {
    var dpr = window.devicePixelRatio || 1;
    var w = Math.max(1, Math.round(canvas.clientWidth * dpr)), h = Math.max(1, Math.round(canvas.clientHeight * dpr));
    if (canvas.width !== w || canvas.height !== h) { canvas.width = w; canvas.height = h; }
    gl.viewport(0, 0, w, h);
    gl.clearColor(1, 1, 1, 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    gl.enable(gl.POLYGON_OFFSET_FILL);
    gl.polygonOffset(1, 1);

    gl.useProgram(faceProg); uniforms(faceProg); disableAll();
    gl.bindBuffer(gl.ARRAY_BUFFER, faceBuf);
    attrib(faceProg, "p", 3, 9, 0); attrib(faceProg, "n", 3, 9, 3); attrib(faceProg, "c", 3, 9, 6);
    gl.drawArrays(gl.TRIANGLES, 0, faceData.length / 9);

    var edgePx = meanEdge * cam.zoom * Math.min(w, h) / 2;
    if (edgesShown()) {
      gl.useProgram(lineProg); uniforms(lineProg); disableAll();
      gl.bindBuffer(gl.ARRAY_BUFFER, edgeBuf);
      gl.disable(gl.POLYGON_OFFSET_FILL);
      gl.uniform2f(gl.getUniformLocation(lineProg, "px"), 2 / w, 2 / h);
      gl.uniform1f(gl.getUniformLocation(lineProg, "width"), Math.max(1, dpr));
      attrib(lineProg, "a", 3, 8, 0); attrib(lineProg, "b", 3, 8, 3); attrib(lineProg, "es", 2, 8, 6);
      gl.drawArrays(gl.TRIANGLES, 0, edgeData.length / 8);
    }
    if (!showDots || byQuality) return;
    gl.useProgram(dotProg); uniforms(dotProg); disableAll();
    gl.uniform1f(gl.getUniformLocation(dotProg, "size"), Math.max(7 * dpr, Math.min(14 * dpr, 0.6 * edgePx)));
    gl.bindBuffer(gl.ARRAY_BUFFER, dotBuf);
    attrib(dotProg, "p", 3, 7, 0); attrib(dotProg, "c", 4, 7, 3);
    var first = edgePx >= 8 * dpr ? 0 : nRegular;
    gl.drawArrays(gl.POINTS, first, dotData.length / 7 - first);
  }
  function edgesShown() {
    var dpr = window.devicePixelRatio || 1;
    var px = meanEdge * cam.zoom * Math.min(canvas.width, canvas.height) / 2;
    return showEdges === null ? px >= 4 * dpr : showEdges;
  }
  var pending = false;
  function redraw() {
    if (pending) return;
    pending = true;
    window.requestAnimationFrame(function () { pending = false; draw(); });
  }

  // ---- mouse -----------------------------------------------------------------
  var drag = null;
  canvas.addEventListener("mousedown", function (ev) {
    drag = { x: ev.clientX, y: ev.clientY, pan: ev.button === 2 || ev.shiftKey };
    ev.preventDefault();
  });
  window.addEventListener("mouseup", function () { drag = null; });
  window.addEventListener("mousemove", function (ev) {
    if (!drag) return;
    var dx = ev.clientX - drag.x, dy = ev.clientY - drag.y;
    drag.x = ev.clientX; drag.y = ev.clientY;
    if (drag.pan) {
      cam.pan[0] += 2 * dx / (canvas.clientWidth || 1);
      cam.pan[1] -= 2 * dy / (canvas.clientHeight || 1);
    } else {
      cam.yaw += dx * 0.01;
      cam.pitch = Math.max(-1.57, Math.min(1.57, cam.pitch + dy * 0.01));
    }
    redraw();
  });
  canvas.addEventListener("wheel", function (ev) {
    cam.zoom *= Math.exp(-ev.deltaY * 0.0015);
    cam.zoom = Math.max(0.05, Math.min(200, cam.zoom));
    ev.preventDefault();
    redraw();
  }, { passive: false });
  canvas.addEventListener("dblclick", function () { reset(); redraw(); });
  window.addEventListener("keydown", function (ev) {
    if (ev.key === "e") showEdges = !edgesShown();
    else if (ev.key === "d") showDots = !showDots;
    else if (ev.key === "q" && QV) { setQuality(!byQuality); return; }
    else return;
    redraw();
  });
  canvas.addEventListener("contextmenu", function (ev) { ev.preventDefault(); });
  window.addEventListener("resize", redraw);

  // ---- cut plane (hex meshes) ----------------------------------------------
  function cutControls() {
    var box = document.getElementById("controls");
    box.innerHTML = '<label>cut <select id="cut-axis"><option>x</option><option>y</option>' +
      '<option>z</option></select> <input id="cut-at" type="range" min="0" max="1000" value="1000"></label>';
    var axis = document.getElementById("cut-axis"), at = document.getElementById("cut-at");
    axis.selectedIndex = cut.axis;
    at.value = Math.round(1000 * Math.min(1, cut.at));
    function update() {
      cut = { axis: axis.selectedIndex, at: at.value / 1000 };
      build(cutQuads()); upload(); redraw();
    }
    axis.addEventListener("change", update);
    at.addEventListener("input", update);
  }

  // ---- legend ------------------------------------------------------------------
  var names = { 3: "valence 3", 4: "valence 4", 5: "valence 5", 0: "other" };
  var legend = document.getElementById("legend");
  function legendRow(cls, rgb, label) {
    var row = document.createElement("div");
    var sw = document.createElement("span");
    sw.className = cls;
    sw.style.background = "rgb(" + rgb.map(Math.round).join(",") + ")";
    row.appendChild(sw);
    row.appendChild(document.createTextNode(label));
    legend.appendChild(row);
  }
  function fillLegend() {
    legend.textContent = "";
    if (!byQuality) {
      [3, 4, 5, 0].forEach(function (code) {
        legendRow("swatch", COLOURS[code], names[code] + ": " + counts[code]);
      });
      return;
    }
    var bands = [[-Infinity, 0, "inverted (\u2264 0)"], [0, 0.5, "0 \u2013 0.5"], [0.5, 0.8, "0.5 \u2013 0.8"],
      [0.8, Infinity, "0.8 \u2013 1"]];
    bands.forEach(function (b) {
      var n = 0;
      for (var i = 0; i < QV.length; i++) if (QV[i] > b[0] && QV[i] <= b[1]) n++;
      var mid = b[0] === -Infinity ? 0 : Math.min(1, 0.5 * (b[0] + Math.min(1, b[1])));
      var rgb = qualityColour(b[0] === -Infinity ? -1 : mid).map(function (x) { return 255 * x; });
      legendRow("bar", rgb, b[2] + ": " + n);
    });
    var min = QV.reduce(function (a, v) { return Math.min(a, v); }, Infinity);
    var note = document.createElement("div");
    note.className = "note";
    note.textContent = "scaled Jacobian per " + (H ? "hex" : "quad") + ", min " +
      (QV.length ? min.toFixed(3) : "none") + (mesh.quality_note ? "; " + mesh.quality_note : "");
    legend.appendChild(note);
  }
  var qualityButton = null;
  function setQuality(on) {
    byQuality = on;
    if (qualityButton) qualityButton.textContent = on ? "colour: quality (q)" : "colour: valence (q)";
    fillLegend();
    build(cutQuads()); upload(); redraw();
  }
  if (QV) {
    qualityButton = document.createElement("button");
    qualityButton.id = "quality-toggle";
    qualityButton.title = "switch between valence dots and elements coloured by scaled Jacobian";
    qualityButton.addEventListener("click", function () { setQuality(!byQuality); });
    document.getElementById("colour").appendChild(qualityButton);
    qualityButton.textContent = byQuality ? "colour: quality (q)" : "colour: valence (q)";
  }
  fillLegend();
  var what = H ? nh + " hexes (" + Q.length / 4 + " boundary quads), " : nq + " quads, ";
  if (H) cutControls();
  if (window.innerWidth < 560 || window.innerHeight < 420) document.getElementById("panel").open = false;
  status.textContent = what + V.length + " vertices. Drag: orbit, wheel: zoom, shift/right drag: pan, double click: reset, e: edges, d: dots" +
    (QV ? ", q: quality colours." : ".");
  reset();
  draw();
})();
