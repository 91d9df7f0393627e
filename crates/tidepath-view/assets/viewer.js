// tidepath view: draws the scene (the JSON in #tp-scene, written by crates/tidepath-view) with
// plotly.js and plays it back. Contract with the browser test (scripts/view_test):
// - <html data-tidepath-state="rendered"> once the first render is on screen, "error" (with
//   data-tidepath-error) when building the scene failed;
// - window.tidepathView = { timeRange, renderMs, setTime(t) -> Promise };
// - after the time slider's input is drawn, <html data-tidepath-time="t">.
(function () {
  "use strict";
  var root = document.documentElement;
  function fail(e) {
    var message = String((e && e.message) || e);
    root.dataset.tidepathState = "error";
    root.dataset.tidepathError = message;
    var plot = document.getElementById("tp-plot");
    if (plot) plot.textContent = "The view could not be drawn: " + message;
    if (window.console) console.error(e);
  }
  try {
    main();
  } catch (e) {
    fail(e);
  }

  function main() {
    var probe = document.createElement("canvas");
    if (!(probe.getContext("webgl2") || probe.getContext("webgl"))) {
      throw new Error("this browser gives no WebGL context: the 3-D view needs WebGL (enable hardware acceleration or use another browser)");
    }
    var S = JSON.parse(document.getElementById("tp-scene").textContent);
    var gd = document.getElementById("tp-plot");
    var PALETTE = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#e377c2", "#bcbd22", "#7f7f7f"];
    var groups = [];
    S.routes.forEach(function (r) { if (groups.indexOf(r.group) < 0) groups.push(r.group); });
    function colourOf(g) { return PALETTE[groups.indexOf(g) % PALETTE.length]; }
    var t0 = S.time.start, t1 = S.time.end;
    var traces = [];
    var dyn = { vehicles: [], obstacles: [], cones: -1, waves: -1, phase: -1, routes: [] };

    document.getElementById("tp-title").textContent = S.title;
    document.getElementById("tp-subtitle").textContent = S.subtitle || "";

    // --- the seabed ---
    if (S.seabed) {
      var sb = S.seabed;
      traces.push({
        type: "surface", name: "seabed", x: sb.x, y: sb.y, z: sb.z, surfacecolor: sb.elevation,
        colorscale: sb.colorscale, cmin: sb.cmin, cmax: sb.cmax, showlegend: true,
        colorbar: { title: { text: "elevation (m)", side: "right" }, len: 0.28, y: 0.83, thickness: 14, x: 1.0 },
        // Hover text per node, made here rather than shipped: place and true elevation.
        text: sb.elevation.map(function (row, j) {
          return row.map(function (h, i) {
            var place = sb.lonlat ? degrees(sb.lonlat[j][i][1], "N", "S") + " " + degrees(sb.lonlat[j][i][0], "E", "W")
              : "x " + sb.x[i].toFixed(0) + " m, y " + sb.y[j].toFixed(0) + " m";
            return place + "<br>" + (h >= 0 ? "land " + h.toFixed(1) + " m high" : "seabed " + (-h).toFixed(1) + " m deep");
          });
        }),
        hoverinfo: "text",
        lighting: { ambient: 0.65, diffuse: 0.6, specular: 0.05, roughness: 0.9 },
        contours: { z: { show: false } }
      });
    }

    // --- waves: a colour on the sea surface ---
    if (S.waves) {
      var wv = S.waves;
      var flat = wv.frames[0].h.map(function (row) { return row.map(function (h) { return h === null ? null : wv.z; }); });
      dyn.waves = traces.length;
      traces.push({
        type: "surface", name: "waves (significant height)", x: wv.x, y: wv.y, z: flat,
        surfacecolor: wv.frames[0].h, cmin: wv.hmin, cmax: wv.hmax, colorscale: "YlGnBu", reversescale: true,
        opacity: 0.8, showlegend: true, showscale: true,
        colorbar: { title: { text: "waves (m)", side: "right" }, len: 0.28, y: 0.5, thickness: 14, x: 1.0 },
        text: waveText(wv.frames[0].h), hoverinfo: "text"
      });
    }

    // --- currents: cones ---
    if (S.currents) {
      var cu = S.currents, f0 = cu.frames[0];
      dyn.cones = traces.length;
      traces.push({
        type: "cone", name: "currents", x: cu.x, y: cu.y, z: cu.z, u: f0.u, v: f0.v, w: f0.w,
        sizemode: "scaled", sizeref: 0.55, anchor: "center", showlegend: true, showscale: true,
        colorscale: "Blues", cmin: 0, cmax: cu.max_speed,
        colorbar: { title: { text: "current (m/s)", side: "right" }, len: 0.28, y: 0.17, thickness: 14, x: 1.0 },
        hoverinfo: "norm+name"
      });
    }

    // --- obstacles ---
    var shownFixed = false, shownMoving = false;
    S.obstacles.forEach(function (o) {
      var legend = o.moving ? !shownMoving : !shownFixed;
      if (o.moving) shownMoving = true; else shownFixed = true;
      var i = traces.length;
      traces.push({
        type: "mesh3d", name: o.moving ? "moving obstacles" : "obstacles", legendgroup: o.moving ? "moving" : "fixed",
        showlegend: legend, x: o.mesh.x, y: o.mesh.y, z: o.mesh.z, i: o.mesh.i, j: o.mesh.j, k: o.mesh.k,
        color: o.moving ? "#f28e2b" : "#9e2a2b", opacity: o.moving ? 0.8 : 0.55, flatshading: true,
        text: o.name, hoverinfo: "text",
        lighting: { ambient: 0.6, diffuse: 0.7 }
      });
      if (o.moving || o.from !== null || o.to !== null) dyn.obstacles.push({ trace: i, o: o });
    });

    // --- routes, their vehicles and violations ---
    var topSpeed = 0;
    S.routes.forEach(function (r) {
      r.sog.forEach(function (v) { if (v > topSpeed) topSpeed = v; });
    });
    var colourMode = S.routes.length > 1 ? "planner" : "speed";
    document.getElementById("tp-colour").value = colourMode;
    S.routes.forEach(function (r, k) {
      var c = colourOf(r.group);
      dyn.routes.push(traces.length);
      traces.push({
        type: "scatter3d", mode: "lines", name: r.label + (r.feasible ? "" : " (" + r.status + ")"),
        legendgroup: "route" + k, x: r.x, y: r.y, z: r.z, text: r.hover, hoverinfo: "text",
        line: lineStyle(r, c, k)
      });
      dyn.vehicles.push(traces.length);
      var p = positionAt(r, t0);
      traces.push({
        type: "scatter3d", mode: "markers", name: r.label + " vehicle", legendgroup: "route" + k, showlegend: false,
        x: [p[0]], y: [p[1]], z: [p[2]], marker: { size: 10, color: c, symbol: "diamond", line: { color: "#111", width: 1.5 } },
        text: r.label + " (vehicle)", hoverinfo: "text"
      });
      if (r.violations.length) {
        traces.push({
          type: "scatter3d", mode: "markers", name: r.label + ": violations", legendgroup: "route" + k,
          x: r.violations.map(function (v) { return v.x; }), y: r.violations.map(function (v) { return v.y; }),
          z: r.violations.map(function (v) { return v.z; }), text: r.violations.map(function (v) { return v.text; }),
          marker: { size: 6, color: "#d50000", symbol: "x" }, hoverinfo: "text"
        });
      }
    });

    // --- a simulation's route ahead after each phase ---
    if (S.phases.length) {
      dyn.phase = traces.length;
      var ph = phaseAt(t0);
      traces.push({
        type: "scatter3d", mode: "lines", name: "route ahead (re-planned)", x: col(ph.route, 0), y: col(ph.route, 1), z: col(ph.route, 2),
        line: { color: "#444", width: 4, dash: "dash" }, text: "route ahead after: " + ph.event, hoverinfo: "text"
      });
    }

    // --- starts and goals ---
    traces.push(endMarkers(S.markers.starts, "start", "#1b9e77", "circle"));
    traces.push(endMarkers(S.markers.goals, "goal", "#111111", "square"));

    // --- layout ---
    var bx = S.bounds.x, by = S.bounds.y, zr = S.z_range;
    var w = Math.max(bx[1] - bx[0], by[1] - by[0]) || 1;
    function aspect(ex) {
      return { x: (bx[1] - bx[0]) / w || 1, y: (by[1] - by[0]) / w || 1, z: Math.min(4, Math.max(0.02, ((zr[1] - zr[0]) / w) * ex)) };
    }
    var geo = S.geo_ticks;
    // A 2-D world without a seabed: z only gives obstacles some height; no depth to read.
    var flatWorld = S.dims === 2 && !S.seabed;
    function axis(title, range, ticks) {
      var a = { title: { text: title }, range: range, backgroundcolor: "#f4f6f8", showbackground: true, gridcolor: "#cfd6dd", zerolinecolor: "#9aa5b1" };
      if (ticks && ticks.vals.length) { a.tickvals = ticks.vals; a.ticktext = ticks.text; }
      return a;
    }
    var ex = S.exaggeration.default;
    var layout = {
      margin: { l: 0, r: 0, t: 0, b: 0 },
      showlegend: true,
      legend: { x: 0.01, y: 0.99, bgcolor: "rgba(255,255,255,0.85)", bordercolor: "#d5dbe1", borderwidth: 1, font: { size: 12 } },
      scene: {
        aspectmode: "manual", aspectratio: aspect(ex),
        xaxis: axis(geo ? "longitude" : "east (m)", bx, geo && geo.x),
        yaxis: axis(geo ? "latitude" : "north (m)", by, geo && geo.y),
        zaxis: flatWorld ? { range: zr, showticklabels: false, title: { text: "" }, showbackground: false, gridcolor: "#e3e8ed" } : axis("elevation (m)", zr, null),
        // A flat world is read from higher up: nothing hides behind anything.
        camera: flatWorld ? { eye: { x: -0.25, y: -0.8, z: 0.95 }, center: { x: 0, y: 0, z: -0.05 } }
          : { eye: { x: -0.72, y: -1.02, z: 0.62 }, center: { x: 0, y: 0, z: -0.12 } }
      },
      uirevision: "keep"
    };
    var config = {
      displaylogo: false, responsive: true, scrollZoom: true,
      modeBarButtonsToRemove: ["resetCameraLastSave3d"],
      toImageButtonOptions: { format: "png", filename: "tidepath-view", scale: 2 }
    };

    panel();
    var slider = document.getElementById("tp-time");
    slider.min = String(t0);
    slider.max = String(t1);
    slider.value = String(t0);
    slider.disabled = !(t1 > t0);
    document.getElementById("tp-play").disabled = !(t1 > t0);
    var exSlider = document.getElementById("tp-exaggeration");
    exSlider.max = String(Math.log10(S.exaggeration.max));
    exSlider.value = String(Math.log10(ex));
    exSlider.disabled = flatWorld;
    showExaggeration(ex);
    clock(t0);

    var api = { timeRange: [t0, t1], renderMs: null, setTime: setTime };
    window.tidepathView = api;
    // A link can open at a moment: view.html#t=3600 (seconds on the scenario's clock).
    var start = /(?:^#|&)t=([-0-9.eE+]+)/.exec(location.hash);
    Plotly.newPlot(gd, traces, layout, config).then(function () {
      if (start && isFinite(parseFloat(start[1]))) {
        slider.value = String(Math.max(t0, Math.min(t1, parseFloat(start[1]))));
        return setTime(parseFloat(slider.value));
      }
    }).then(function () {
      // Two frames later the WebGL canvas holds the first picture.
      requestAnimationFrame(function () {
        requestAnimationFrame(function () {
          api.renderMs = performance.now();
          root.dataset.tidepathState = "rendered";
        });
      });
    }, fail);

    // --- controls ---
    var busy = null;
    slider.addEventListener("input", function () { setTime(parseFloat(slider.value)); });
    exSlider.addEventListener("input", function () {
      var e = Math.pow(10, parseFloat(exSlider.value));
      showExaggeration(e);
      Plotly.relayout(gd, { "scene.aspectratio": aspect(e) });
    });
    document.getElementById("tp-colour").addEventListener("change", function (ev) {
      colourMode = ev.target.value;
      var lines = S.routes.map(function (r, k) { return lineStyle(r, colourOf(r.group), k); });
      Plotly.restyle(gd, { line: lines }, dyn.routes);
    });
    var playing = false, last = 0;
    var play = document.getElementById("tp-play");
    play.addEventListener("click", function () {
      playing = !playing;
      play.innerHTML = playing ? "&#10073;&#10073; Pause" : "&#9654; Play";
      if (playing) {
        if (parseFloat(slider.value) >= t1) slider.value = String(t0);
        last = performance.now();
        requestAnimationFrame(step);
      }
    });
    function step(now) {
      if (!playing) return;
      // The whole mission in about 20 seconds.
      var dt = ((now - last) / 1000) * ((t1 - t0) / 20);
      last = now;
      var t = Math.min(t1, parseFloat(slider.value) + dt);
      slider.value = String(t);
      if (!busy) setTime(t);
      if (t >= t1) { playing = false; play.innerHTML = "&#9654; Play"; return; }
      requestAnimationFrame(step);
    }

    function setTime(t) {
      t = Math.max(t0, Math.min(t1, t));
      clock(t);
      var jobs = [];
      if (dyn.vehicles.length) {
        var ps = S.routes.map(function (r) { return positionAt(r, t); });
        jobs.push(Plotly.restyle(gd, {
          x: ps.map(function (p) { return [p[0]]; }), y: ps.map(function (p) { return [p[1]]; }), z: ps.map(function (p) { return [p[2]]; })
        }, dyn.vehicles));
      }
      if (dyn.obstacles.length) {
        var u = { x: [], y: [], z: [] };
        dyn.obstacles.forEach(function (d) {
          var o = d.o, on = (o.from === null || o.from <= t) && (o.to === null || t < o.to || (t === t1 && t <= o.to));
          var v = o.velocity;
          u.x.push(on ? o.mesh.x.map(function (a) { return a + v[0] * t; }) : []);
          u.y.push(on ? o.mesh.y.map(function (a) { return a + v[1] * t; }) : []);
          u.z.push(on ? o.mesh.z.map(function (a) { return a + v[2] * t; }) : []);
        });
        jobs.push(Plotly.restyle(gd, u, dyn.obstacles.map(function (d) { return d.trace; })));
      }
      if (dyn.cones >= 0 && S.currents.frames.length > 1) {
        var f = frameAt(S.currents.frames, t);
        jobs.push(Plotly.restyle(gd, { u: [f.u], v: [f.v], w: [f.w] }, [dyn.cones]));
      }
      if (dyn.waves >= 0 && S.waves.frames.length > 1) {
        var wf = frameAt(S.waves.frames, t).h;
        jobs.push(Plotly.restyle(gd, { surfacecolor: [wf], text: [waveText(wf)] }, [dyn.waves]));
      }
      if (dyn.phase >= 0) {
        var ph = phaseAt(t);
        jobs.push(Plotly.restyle(gd, {
          x: [col(ph.route, 0)], y: [col(ph.route, 1)], z: [col(ph.route, 2)],
          text: ["route ahead after: " + ph.event]
        }, [dyn.phase]));
      }
      busy = Promise.all(jobs).then(function () {
        busy = null;
        root.dataset.tidepathTime = String(t);
      }, fail);
      return busy;
    }

    // --- helpers ---
    function lineStyle(r, c, k) {
      if (colourMode === "speed") {
        return {
          width: 7, color: r.sog, colorscale: "Viridis", cmin: 0, cmax: topSpeed || 1, showscale: k === 0,
          colorbar: { title: { text: "speed over ground (m/s)", side: "right" }, x: -0.02, xanchor: "left", len: 0.45, y: 0.3, thickness: 14 }
        };
      }
      return { width: 6, color: c };
    }
    function positionAt(r, t) {
      var n = r.t.length;
      if (!n) return [null, null, null];
      if (t <= r.t[0]) return [r.x[0], r.y[0], r.z[0]];
      if (t >= r.t[n - 1]) return [r.x[n - 1], r.y[n - 1], r.z[n - 1]];
      var lo = 0, hi = n - 1;
      while (hi - lo > 1) { var mid = (lo + hi) >> 1; if (r.t[mid] <= t) lo = mid; else hi = mid; }
      var span = r.t[hi] - r.t[lo], s = span > 0 ? (t - r.t[lo]) / span : 0;
      return [r.x[lo] + s * (r.x[hi] - r.x[lo]), r.y[lo] + s * (r.y[hi] - r.y[lo]), r.z[lo] + s * (r.z[hi] - r.z[lo])];
    }
    function frameAt(frames, t) {
      var f = frames[0];
      for (var i = 1; i < frames.length; i++) if (frames[i].t <= t) f = frames[i];
      return f;
    }
    function phaseAt(t) {
      var p = S.phases[0];
      for (var i = 1; i < S.phases.length; i++) if (S.phases[i].t <= t) p = S.phases[i];
      return p;
    }
    function waveText(h) {
      return h.map(function (row) { return row.map(function (v) { return v === null ? "no wave data" : "wave height " + v.toFixed(2) + " m"; }); });
    }
    function degrees(v, pos, neg) { return Math.abs(v).toFixed(4) + "°" + (v < 0 ? neg : pos); }
    function col(points, k) { return points.map(function (p) { return p[k]; }); }
    function endMarkers(list, what, colour, symbol) {
      return {
        type: "scatter3d", mode: "markers", name: what, x: list.map(function (m) { return m.at[0]; }),
        y: list.map(function (m) { return m.at[1]; }), z: list.map(function (m) { return m.at[2]; }),
        text: list.map(function (m) { return what + " of " + m.name; }),
        marker: { size: 7, color: colour, symbol: symbol, line: { color: "#fff", width: 1 } },
        hoverinfo: "text"
      };
    }
    function clock(t) {
      var s = "t = " + t.toFixed(0) + " s";
      if (t1 > t0) s += " of " + t1.toFixed(0);
      if (S.time.epoch) {
        var d = new Date(Date.parse(S.time.epoch) + t * 1000);
        if (!isNaN(d.getTime())) s += " · " + d.toISOString().slice(0, 19).replace("T", " ") + " UTC";
      }
      document.getElementById("tp-clock").textContent = s;
    }
    function showExaggeration(e) {
      document.getElementById("tp-exaggeration-value").textContent = " " + (e >= 10 ? e.toFixed(0) : e.toFixed(1));
    }
    function panel() {
      var box = document.getElementById("tp-routes");
      if (!S.routes.length) box.textContent = "No route: the scenario alone.";
      S.routes.forEach(function (r) {
        var d = document.createElement("div");
        d.className = "tp-route";
        var head = document.createElement("div");
        var sw = document.createElement("span");
        sw.className = "tp-swatch";
        sw.style.background = colourOf(r.group);
        head.appendChild(sw);
        var name = document.createElement("b");
        name.textContent = r.label;
        head.appendChild(name);
        var st = document.createElement("span");
        st.textContent = " " + r.status;
        if (!r.feasible) st.className = "tp-bad";
        head.appendChild(st);
        d.appendChild(head);
        var rows = [["cost", r.cost === null ? "none" : r.cost.toPrecision(6)], ["length", (r.length_m / 1000).toFixed(2) + " km"]];
        if (r.t.length > 1) rows.push(["travel time", ((r.t[r.t.length - 1] - r.t[0]) / 60).toFixed(1) + " min"]);
        r.terms.forEach(function (kv) { rows.push(["term: " + kv[0], Number(kv[1]).toPrecision(5)]); });
        var tb = document.createElement("table");
        rows.forEach(function (row) {
          var tr = document.createElement("tr");
          row.forEach(function (cell) { var td = document.createElement("td"); td.textContent = cell; tr.appendChild(td); });
          tb.appendChild(tr);
        });
        d.appendChild(tb);
        box.appendChild(d);
      });
      var notes = [
        "Drag to turn, scroll to zoom, right-drag to pan; click a legend entry to hide or show it.",
        "Hover a path for its time, depth, clearance and its segment's cost terms."
      ];
      if (S.seabed) notes.push("Seabed sampled at " + S.seabed.nodes[0] + " × " + S.seabed.nodes[1] + " nodes; each node holds the terrain's own height there.");
      if (!flatWorld) notes.push("Vertical exaggeration " + S.exaggeration.default + "× by default: depths are small beside distances.");
      else notes.push("A 2-D world: obstacles are drawn as walls; the height has no meaning.");
      if (S.currents && S.currents.frames.length > 1) notes.push("Currents change over time: " + S.currents.frames.length + " sampled frames follow the slider.");
      if (S.phases.length) notes.push("Simulation: the dashed line is the route ahead after the latest phase (" + S.phases.length + " phases).");
      var ul = document.getElementById("tp-notes");
      notes.forEach(function (n) { var li = document.createElement("li"); li.textContent = n; ul.appendChild(li); });
    }
  }
})();
