/* balance animate: an engine turning through its cycle, beside the forward and backward
   phasors of its shaking force and free moment (balance_cli/plot/page.py writes the data).

   Every position drawn is one of the data's: the kinematic state's frames, or a firing's own
   instant after a step to it; nothing is interpolated. Each cylinder's share of every order
   is in the data, so that leaving a cylinder out is a subtraction, with the free moment taken
   about the remaining cylinders' mean axial position, as balance analyses the engine without
   it. Each animation on a page is mounted once; window.balanceAnimations lists them. */
(function () {
  "use strict";
  var SVG = "http://www.w3.org/2000/svg";
  var DATA_CLASS = "balance-animation-data";
  /* a cylinder is marked as firing for this many degrees after its firing TDC */
  var FIRING_MARK = 45;
  var TICK_MS = 40;
  var COLOURS = {
    forward: "#1f77b4", backward: "#d62728", sum: "#000", trace: "#ff7f0e", fire: "#ff8c00",
    piston: "#d9d9d9", rod: "#4a6f8a", crank: "#555", bore: "#b3b3b3", weight: "#000",
    balancer: "#2ca02c", faint: "#ccc"
  };
  var registry = window.balanceAnimations = window.balanceAnimations || [];

  function node(name, attrs, parent) {
    var element = document.createElementNS(SVG, name);
    set(element, attrs);
    if (parent) { parent.appendChild(element); }
    return element;
  }

  function html(name, attrs, parent, text) {
    var element = document.createElement(name);
    Object.keys(attrs || {}).forEach(function (key) { element.setAttribute(key, attrs[key]); });
    if (text !== undefined) { element.textContent = text; }
    if (parent) { parent.appendChild(element); }
    return element;
  }

  function set(element, attrs) {
    Object.keys(attrs || {}).forEach(function (key) { element.setAttribute(key, attrs[key]); });
  }

  function fixed(value) { return Math.round(value * 100) / 100; }

  /* four significant figures, thousands set apart by spaces (as balance prints them) */
  function significant(value) {
    if (value === 0 || !isFinite(value)) { return value === 0 ? "0" : String(value); }
    var exponent = Math.floor(Math.log10(Math.abs(Number(value.toPrecision(4)))));
    if (exponent < -4 || exponent >= 9) { return value.toExponential(3); }
    var text = value.toFixed(Math.max(3 - exponent, 0));
    var parts = text.split(".");
    parts[0] = parts[0].replace(/\B(?=(\d{3})+(?!\d))/g, " ");
    return parts.join(".");
  }

  /* a whole number, thousands set apart */
  function spaced(value) {
    return String(Math.round(value)).replace(/\B(?=(\d{3})+(?!\d))/g, " ");
  }

  function decode(pair) {
    var n = pair[0].length, re = new Float64Array(n), im = new Float64Array(n);
    for (var i = 0; i < n; i++) { re[i] = pair[0][i] * 1e-6; im[i] = pair[1][i] * 1e-6; }
    return { re: re, im: im };
  }

  function Animation(root, data) {
    var self = this;
    this.root = root;
    this.data = data;
    this.turns = data.cycle / 360;
    this.step = 360 / data.frames;
    this.points = {};
    this.eventPoints = {};
    Object.keys(data.points).forEach(function (name) {
      self.points[name] = decode(data.points[name]);
      self.eventPoints[name] = decode(data.eventPoints[name]);
    });
    this.on = {};
    data.groups.forEach(function (g) { if (g.cylinder) { self.on[g.cylinder] = true; } });
    this.ordersOn = {};
    data.shown.forEach(function (k) { self.ordersOn[k] = true; });
    this.angle = 0;
    this.event = null;
    this.playing = true;
    this.speed = data.cycle / 6;
    this.build();
    this.compute();
    this.draw();
    this.last = performance.now();
    this.tick = function () {
      var now = performance.now();
      if (self.playing) {
        self.angle = (self.angle + self.speed * (now - self.last) / 1000) % data.cycle;
        self.event = null;
        self.draw();
      }
      self.last = now;
      window.setTimeout(self.tick, TICK_MS);
    };
    window.setTimeout(this.tick, TICK_MS);
  }

  /* --- what is shown: the drawn instant, the cylinders and orders on ------------------- */

  Animation.prototype.drawn = function () {
    if (this.event !== null) {
      return { angle: this.data.events[this.event][0], frame: null, event: this.event };
    }
    var count = this.data.frames * this.turns;
    var index = Math.round(this.angle / this.step) % count;
    return { angle: index * this.step, frame: index % this.data.frames, event: null };
  };

  Animation.prototype.at = function (name, now) {
    if (name in this.data.fixed) {
      return { re: this.data.fixed[name][0], im: this.data.fixed[name][1] };
    }
    var series = now.event === null ? this.points[name] : this.eventPoints[name];
    var i = now.event === null ? now.frame : now.event;
    return { re: series.re[i], im: series.im[i] };
  };

  Animation.prototype.firing = function (angle) {
    var cycle = this.data.cycle, out = {};
    this.data.events.forEach(function (event) {
      if ((((angle - event[0]) % cycle) + cycle) % cycle < FIRING_MARK - 1e-9) {
        out[event[1]] = true;
      }
    });
    return out;
  };

  /* each order's phasors with the cylinders on: shares summed, the moment about their own
     mean axial position, and what is below the noise floor of that engine made zero */
  Animation.prototype.compute = function () {
    var d = this.data, self = this;
    var kept = d.groups.map(function (g) { return !g.cylinder || self.on[g.cylinder]; });
    var cylinders = d.groups.filter(function (g) { return g.cylinder && self.on[g.cylinder]; });
    var mean = 0, mass = 0;
    cylinders.forEach(function (g) { mean += g.z_m; mass += g.reciprocating_kg; });
    mean /= cylinders.length;
    var lever = d.crankRadius;
    cylinders.forEach(function (g) { lever = Math.max(lever, Math.abs(g.z_m - mean)); });
    var floorN = d.noiseFloor * mass * d.unitN, floorNm = floorN * lever;
    this.floors = { force: floorN, moment: floorNm };
    this.values = d.orders.map(function (k, i) {
      var f = [0, 0, 0, 0], m = [0, 0, 0, 0];
      d.groups.forEach(function (g, j) {
        if (!kept[j]) { return; }
        for (var c = 0; c < 4; c++) { f[c] += d.force[j][i][c]; m[c] += d.moment[j][i][c]; }
      });
      for (var c = 0; c < 4; c++) { m[c] -= (mean - d.meanZ) * f[c]; }
      return { order: k, force: clean(f, floorN), moment: clean(m, floorNm) };
    });
  };

  function clean(values, floor) {
    var out = values.slice();
    if (Math.hypot(out[0], out[1]) < floor) { out[0] = 0; out[1] = 0; }
    if (Math.hypot(out[2], out[3]) < floor) { out[2] = 0; out[3] = 0; }
    return out;
  }

  /* the order-k phasor pair p at engine angle theta (rad): [forward, backward] turned */
  function turned(p, k, theta) {
    var c = Math.cos(k * theta), s = Math.sin(k * theta);
    return [
      { re: p[0] * c - p[1] * s, im: p[0] * s + p[1] * c },
      { re: p[2] * c + p[3] * s, im: p[3] * c - p[2] * s }
    ];
  }

  Animation.prototype.resultant = function (quantity, theta) {
    var self = this, total = { re: 0, im: 0 };
    this.values.forEach(function (v) {
      if (!self.ordersOn[v.order]) { return; }
      var pair = turned(v[quantity], v.order, theta);
      total.re += pair[0].re + pair[1].re;
      total.im += pair[0].im + pair[1].im;
    });
    return total;
  };

  /* --- building the page ----------------------------------------------------------------- */

  Animation.prototype.build = function () {
    var d = this.data, self = this, root = this.root;
    html("div", { "class": "ba-title" }, root, d.name);
    var controls = html("div", { "class": "ba-controls" }, root);
    this.playButton = html("button", { type: "button", "class": "ba-play" }, controls, "❚❚ pause");
    this.playButton.addEventListener("click", function () {
      if (self.playing) { self.pause(); } else { self.play(); }
    });
    var tdc = html("button", { type: "button", "class": "ba-tdc" }, controls, "next firing TDC ▸");
    tdc.addEventListener("click", function () { self.stepTDC(); });
    var speed = html("label", {}, controls, "speed ");
    this.slider = html("input", {
      type: "range", min: "10", max: String(4 * d.cycle), step: "10", value: String(this.speed)
    }, speed);
    this.speedText = html("span", {}, speed);
    this.slider.addEventListener("input", function () { self.setSpeed(Number(self.slider.value)); });
    this.setSpeed(this.speed);
    var orders = html("fieldset", {}, controls);
    html("legend", {}, orders, "orders");
    this.orderBoxes = {};
    d.orders.forEach(function (k) {
      var label = html("label", {}, orders);
      var box = html("input", { type: "checkbox", "data-order": String(k) }, label);
      box.checked = !!self.ordersOn[k];
      label.appendChild(document.createTextNode(" " + k + " "));
      box.addEventListener("change", function () { self.setOrder(k, box.checked); });
      self.orderBoxes[k] = box;
    });
    var cylinders = html("fieldset", {}, controls);
    html("legend", {}, cylinders, "cylinders");
    this.cylinderBoxes = {};
    d.groups.forEach(function (g) {
      if (!g.cylinder) { return; }
      var label = html("label", {}, cylinders);
      var box = html("input", { type: "checkbox", "data-cylinder": String(g.cylinder) }, label);
      box.checked = true;
      if (!g.toggle) {
        box.disabled = true;
        label.title = "its master rod carries link rods: the engine cannot run without it";
      }
      label.appendChild(document.createTextNode(" " + g.cylinder + " "));
      box.addEventListener("change", function () {
        if (!self.setCylinder(g.cylinder, box.checked)) { box.checked = true; }
      });
      self.cylinderBoxes[g.cylinder] = box;
    });
    this.readout = html("div", { "class": "ba-readout" }, root);
    var holder = html("div", { "class": "ba-mechanism" }, root);
    var lay = d.layout;
    this.svg = node("svg", {
      width: lay.width, height: lay.height, viewBox: "0 0 " + lay.width + " " + lay.height,
      "class": "ba-views", role: "img", "aria-label": d.name + ", turning"
    }, holder);
    this.views = [this.buildView("end", lay.end)];
    if (lay.side) { this.views.push(this.buildView("side", lay.side)); }
    var panels = html("div", { "class": "ba-panels" }, root);
    this.dial = this.buildDial(panels);
    this.panels = [];
    ["force", "moment"].forEach(function (quantity) {
      d.orders.forEach(function (k) { self.panels.push(self.buildPanel(panels, quantity, k)); });
      self.panels.push(self.buildPanel(panels, quantity, null));
    });
    html("div", { "class": "ba-note" }, root,
      "Seen along the crank axis, the crank turning clockwise" + (lay.side ? "; and from the side" : "") +
      ". F: the shaking force's phasors (N), M: the free moment's about the engine's mid-length " +
      "(N·m), order by order as balance compare reports them: forward (blue) turns with the " +
      "crank, backward (red) from its tip against it, their sum dashed; the last panel of each " +
      "row is the resultant of the orders on, its locus traced in orange since the revolution " +
      "began. A cylinder left out is subtracted from the phasors, the moment then taken about " +
      "the remaining cylinders' mid-length. The pistons shown orange are firing.");
  };

  Animation.prototype.buildView = function (name, place) {
    var d = this.data, self = this;
    var view = {
      name: name, x0: place[0], y0: place[1], s: place[2], left: place[3], top: place[4],
      g: node("g", { "class": "ba-" + name }, this.svg), parts: []
    };
    node("text", {
      x: view.x0 + 4, y: 14, "font-size": "12", fill: "#444"
    }, view.g).textContent = name === "end" ? "seen along the crank axis" : "seen from the side";
    if (name === "end") {
      Object.keys(d.fixed).forEach(function (key) {
        var p = self.xy(view, { re: d.fixed[key][0], im: d.fixed[key][1] }, 0);
        node("circle", {
          cx: p[0], cy: p[1], r: d.crankRadius * view.s, fill: "none", stroke: "#ddd"
        }, view.g);
      });
      if (d.rotary) {
        view.case = node("polygon", { fill: "none", stroke: "#777", "stroke-width": 1.5 }, view.g);
      }
    }
    var layers = ["bore", "axis", "crank", "weight", "balancer", "plate", "rod", "piston"];
    layers.forEach(function (kind) {
      d.parts.forEach(function (raw) {
        if (raw[0] !== kind) { return; }
        var part = {
          kind: raw[0], points: raw[1], z: raw[2], cylinder: raw[3], axis: raw[4],
          outward: raw[5], span: raw[6]
        };
        self.buildPart(view, part);
        view.parts.push(part);
      });
    });
    return view;
  };

  Animation.prototype.buildPart = function (view, part) {
    var g = view.g;
    var tag = part.cylinder ? { "data-cylinder": String(part.cylinder) } : {};
    if (part.kind === "bore") {
      part.el = node("path", Object.assign({ fill: "none", stroke: COLOURS.bore }, tag), g);
    } else if (part.kind === "axis") {
      var c = this.xy(view, this.at(part.points[0], { event: null, frame: 0 }), 0);
      if (view.name === "end") {
        node("path", {
          d: "M" + (c[0] - 6) + "," + c[1] + "h12M" + c[0] + "," + (c[1] - 6) + "v12",
          stroke: "#000"
        }, g);
      } else {
        node("line", {
          x1: view.x0, y1: c[1], x2: this.data.layout.width, y2: c[1], stroke: "#999",
          "stroke-dasharray": "6 3 1 3"
        }, g);
      }
    } else if (part.kind === "piston") {
      part.el = node("polygon", Object.assign({
        fill: COLOURS.piston, "fill-opacity": 0.85, stroke: "#4d4d4d"
      }, tag), g);
      part.pin = node("circle", Object.assign({
        r: 2.5, fill: "#000", "data-point": part.points[0]
      }, tag), g);
      part.spark = node("polygon", {
        points: star(), fill: COLOURS.fire, visibility: "hidden"
      }, g);
    } else {
      var colour = {
        crank: COLOURS.crank, rod: COLOURS.rod, plate: COLOURS.rod, weight: COLOURS.weight,
        balancer: COLOURS.balancer
      }[part.kind];
      var thickness = { crank: 5, rod: 2.2, plate: 3.5, weight: 3, balancer: 2 }[part.kind];
      part.el = node("line", Object.assign({
        stroke: colour, "stroke-width": thickness, "stroke-linecap": "round"
      }, tag), g);
      if (part.kind === "weight" || part.kind === "balancer") {
        part.mass = node("circle", { r: part.kind === "weight" ? 6 : 4.5, fill: colour }, g);
      }
    }
  };

  /* a five-pointed star about (0, 0), 9 px across */
  function star() {
    var out = [];
    for (var i = 0; i < 10; i++) {
      var r = i % 2 ? 3.6 : 9, a = Math.PI * i / 5;
      out.push(fixed(r * Math.sin(a)) + "," + fixed(-r * Math.cos(a)));
    }
    return out.join(" ");
  }

  /* a point (m) in a view's pixels: the end view x across the reference axis, y along it
     (up); the side view x axial, y along its vertical */
  Animation.prototype.xy = function (view, p, z) {
    if (view.name === "end") {
      return [view.x0 + view.s * (p.im - view.left), view.y0 + view.s * (view.top - p.re)];
    }
    var u = this.data.side;
    var along = p.re * Math.cos(u) + p.im * Math.sin(u);
    return [view.x0 + view.s * (z - view.left), view.y0 + view.s * (view.top - along)];
  };

  Animation.prototype.buildDial = function (parent) {
    var d = this.data, size = 130, c = size / 2, r = 44;
    var svg = node("svg", { width: size, height: size, "class": "ba-dial" }, parent);
    node("circle", { cx: c, cy: c, r: r, fill: "none", stroke: "#999" }, svg);
    var byAngle = {};
    d.events.forEach(function (event) {
      var key = event[0].toFixed(6);
      (byAngle[key] = byAngle[key] || []).push(event[1]);
    });
    Object.keys(byAngle).forEach(function (key) {
      var a = 2 * Math.PI * Number(key) / d.cycle, s = Math.sin(a), k = Math.cos(a);
      node("line", {
        x1: c + (r - 5) * s, y1: c - (r - 5) * k, x2: c + (r + 3) * s, y2: c - (r + 3) * k,
        stroke: COLOURS.fire, "stroke-width": 2
      }, svg);
      node("text", {
        x: c + (r + 12) * s, y: c - (r + 12) * k + 4, "font-size": "10", "text-anchor": "middle"
      }, svg).textContent = byAngle[key].join(",");
    });
    node("text", { x: c, y: c + 16, "font-size": "9", "text-anchor": "middle", fill: "#666" }, svg)
      .textContent = d.cycle + "° cycle";
    return { hand: node("line", { x1: c, y1: c, stroke: "#000", "stroke-width": 2 }, svg), c: c, r: r };
  };

  Animation.prototype.buildPanel = function (parent, quantity, order) {
    var size = this.data.panel;
    var svg = node("svg", {
      width: size, height: size + 6, "class": "ba-panel",
      "data-quantity": quantity, "data-order": order === null ? "sum" : String(order)
    }, parent);
    var panel = {
      svg: svg, quantity: quantity, order: order, c: [size / 2, size / 2 + 10],
      radius: size / 2 - 16
    };
    panel.title = node("text", {
      x: size / 2, y: 12, "font-size": "11", "text-anchor": "middle"
    }, svg);
    node("path", {
      d: "M" + (panel.c[0] - 4) + "," + panel.c[1] + "h8M" + panel.c[0] + "," + (panel.c[1] - 4) + "v8",
      stroke: "#999"
    }, svg);
    panel.locus = node("path", { fill: "none", stroke: COLOURS.faint }, svg);
    if (order === null) {
      panel.trace = node("path", { fill: "none", stroke: COLOURS.trace, "stroke-width": 2 }, svg);
      panel.now = node("line", { stroke: COLOURS.sum, "stroke-width": 2 }, svg);
    } else {
      panel.forward = node("line", { stroke: COLOURS.forward, "stroke-width": 2 }, svg);
      panel.backward = node("line", { stroke: COLOURS.backward, "stroke-width": 2 }, svg);
      panel.sum = node("line", { stroke: COLOURS.sum, "stroke-dasharray": "4 3" }, svg);
    }
    return panel;
  };

  /* --- drawing ------------------------------------------------------------------------------ */

  Animation.prototype.draw = function () {
    var self = this, d = this.data, now = this.drawn();
    var firing = this.firing(now.angle);
    var theta = now.angle * Math.PI / 180;
    var turn = d.rotary ? theta : 0;
    this.views.forEach(function (view) { self.drawView(view, now, firing, turn); });
    var a = 2 * Math.PI * now.angle / d.cycle, dial = this.dial;
    set(dial.hand, {
      x2: fixed(dial.c + (dial.r - 8) * Math.sin(a)), y2: fixed(dial.c - (dial.r - 8) * Math.cos(a))
    });
    this.panels.forEach(function (panel) { self.drawPanel(panel, theta); });
    var names = Object.keys(firing);
    this.readout.textContent = "engine angle " + now.angle.toFixed(now.event === null ? 1 : 2) +
      "° of " + d.cycle + "°" + (names.length ? " · firing: cylinder " + names.join(", ") : "") +
      (now.event === null ? "" : " (firing TDC)");
    this.shown = now;
    this.drawnAt = performance.now();
  };

  Animation.prototype.drawView = function (view, now, firing, turn) {
    var self = this, d = this.data;
    view.parts.forEach(function (part) {
      var off = part.cylinder && !self.on[part.cylinder];
      if (part.el) { part.el.setAttribute("opacity", off ? 0.2 : 1); }
      if (part.kind === "bore") {
        if (!part.drawn || d.rotary) { part.el.setAttribute("d", self.bore(view, part, turn)); }
        part.drawn = true;
      } else if (part.kind === "piston") {
        self.drawPiston(view, part, now, firing, turn, off);
      } else if (part.kind !== "axis") {
        var a = self.xy(view, self.at(part.points[0], now), self.z(part.points[0], part));
        var b = self.xy(view, self.at(part.points[1], now), self.z(part.points[1], part));
        set(part.el, { x1: fixed(a[0]), y1: fixed(a[1]), x2: fixed(b[0]), y2: fixed(b[1]) });
        if (part.mass) { set(part.mass, { cx: fixed(b[0]), cy: fixed(b[1]) }); }
      }
    });
    if (view.case) {
      var corners = [], radius = Infinity, axes = {};
      view.parts.forEach(function (part) {
        if (part.kind === "bore") { axes[part.axis] = true; radius = Math.min(radius, part.span[0]); }
      });
      Object.keys(axes).map(Number).sort(function (x, y) { return x - y; }).forEach(function (axis) {
        var p = self.xy(view, { re: radius * Math.cos(axis + turn), im: radius * Math.sin(axis + turn) }, 0);
        corners.push(fixed(p[0]) + "," + fixed(p[1]));
      });
      view.case.setAttribute("points", corners.join(" "));
    }
  };

  Animation.prototype.z = function (name, part) {
    return name in this.data.z ? this.data.z[name] : part.z;
  };

  Animation.prototype.drawPiston = function (view, part, now, firing, turn, off) {
    var d = this.data;
    var pin = this.at(part.points[0], now);
    var a = part.axis + turn;
    var u = { re: Math.cos(a) * part.outward, im: Math.sin(a) * part.outward };
    var low = -d.pinAt * d.piston, high = (1 - d.pinAt) * d.piston, half = d.bore / 2;
    var corners, p = this.xy(view, pin, part.z), spark;
    if (view.name === "end") {
      var across = { re: -u.im * half, im: u.re * half };
      corners = [[low, -1], [high, -1], [high, 1], [low, 1]].map(function (c) {
        return { re: pin.re + c[0] * u.re + c[1] * across.re, im: pin.im + c[0] * u.im + c[1] * across.im };
      });
      spark = { re: pin.re + (high + 0.3 * d.piston) * u.re, im: pin.im + (high + 0.3 * d.piston) * u.im };
      var self = this;
      corners = corners.map(function (c) { return self.xy(view, c, part.z); });
      spark = this.xy(view, spark, part.z);
    } else {
      var along = u.re * Math.cos(d.side) + u.im * Math.sin(d.side), s = view.s;
      corners = [
        [p[0] - s * half, p[1] - s * low * along], [p[0] - s * half, p[1] - s * high * along],
        [p[0] + s * half, p[1] - s * high * along], [p[0] + s * half, p[1] - s * low * along]
      ];
      spark = [p[0], p[1] - s * (high + 0.3 * d.piston) * along];
    }
    part.el.setAttribute("points", corners.map(function (c) { return fixed(c[0]) + "," + fixed(c[1]); }).join(" "));
    var fires = firing[part.cylinder] && part.outward === 1 && !off;
    part.el.setAttribute("fill", fires ? COLOURS.fire : COLOURS.piston);
    set(part.pin, { cx: p[0], cy: p[1], opacity: off ? 0.2 : 1 });
    set(part.spark, {
      transform: "translate(" + fixed(spark[0]) + "," + fixed(spark[1]) + ")",
      visibility: fires ? "visible" : "hidden"
    });
  };

  /* a bore's two walls */
  Animation.prototype.bore = function (view, part, turn) {
    var d = this.data, self = this, half = 0.52 * d.bore;
    var centre = this.at(part.points[0], { event: null, frame: 0 });
    var a = part.axis + turn, u = { re: Math.cos(a), im: Math.sin(a) };
    if (view.name === "end") {
      var path = "";
      [-1, 1].forEach(function (side) {
        var ends = part.span.map(function (r) {
          return self.xy(view, {
            re: centre.re + r * u.re - side * u.im * half, im: centre.im + r * u.im + side * u.re * half
          }, 0);
        });
        path += "M" + fixed(ends[0][0]) + "," + fixed(ends[0][1]) + "L" + fixed(ends[1][0]) + "," + fixed(ends[1][1]);
      });
      return path;
    }
    var c = this.xy(view, centre, part.z), along = Math.cos(part.axis - d.side), s = view.s;
    var y0 = fixed(c[1] - s * part.span[0] * along), y1 = fixed(c[1] - s * part.span[1] * along);
    var x0 = fixed(c[0] - s * half), x1 = fixed(c[0] + s * half);
    return "M" + x0 + "," + y0 + "L" + x0 + "," + y1 + "M" + x1 + "," + y0 + "L" + x1 + "," + y1;
  };

  /* where the phasor panels' scales and loci change: a cylinder or an order on or off */
  Animation.prototype.rescale = function () {
    var self = this;
    this.panels.forEach(function (panel) {
      var unit = panel.quantity === "force" ? "N" : "N·m";
      var floor = self.floors[panel.quantity];
      var shown = panel.order === null || self.ordersOn[panel.order];
      panel.svg.style.display = shown ? "" : "none";
      var locus = [], largest = 0, i;
      if (panel.order === null) {
        for (i = 0; i <= 180; i++) { locus.push(self.resultant(panel.quantity, 2 * Math.PI * i / 180)); }
        locus.forEach(function (p) { largest = Math.max(largest, Math.hypot(p.re, p.im)); });
        if (largest < floor) { largest = 0; }
      } else {
        var v = self.values[self.data.orders.indexOf(panel.order)][panel.quantity];
        largest = Math.hypot(v[0], v[1]) + Math.hypot(v[2], v[3]);
        for (i = 0; i <= 120; i++) {
          var pair = turned(v, panel.order, 2 * Math.PI * i / 120);
          locus.push({ re: pair[0].re + pair[1].re, im: pair[0].im + pair[1].im });
        }
      }
      var orders = self.data.orders.filter(function (k) { return self.ordersOn[k]; });
      var name = (panel.quantity === "force" ? "F" : "M");
      var label = panel.order === null ?
        (orders.length ? orders.map(function (k) { return name + k; }).join("+") : "no order on") :
        name + panel.order;
      panel.title.textContent = label + ": " + (largest ? significant(largest) + " " + unit : "none");
      panel.scale = largest ? panel.radius / largest : 0;
      panel.locus.setAttribute("d", largest ? self.path(panel, locus) : "");
      panel.largest = largest;
    });
  };

  Animation.prototype.path = function (panel, points) {
    var self = this;
    return points.map(function (p, i) {
      var q = self.panelXY(panel, p);
      return (i ? "L" : "M") + fixed(q[0]) + "," + fixed(q[1]);
    }).join("");
  };

  Animation.prototype.panelXY = function (panel, p) {
    return [panel.c[0] + panel.scale * p.im, panel.c[1] - panel.scale * p.re];
  };

  Animation.prototype.drawPanel = function (panel, theta) {
    if (panel.scale === undefined) { this.rescale(); }
    var c = panel.c;
    if (panel.order === null) {
      var done = [], revolution = theta % (2 * Math.PI);
      for (var a = 0; a < revolution; a += Math.PI / 90) { done.push(this.resultant(panel.quantity, a)); }
      var now = this.resultant(panel.quantity, revolution);
      done.push(now);
      panel.trace.setAttribute("d", panel.scale ? this.path(panel, done) : "");
      var q = panel.scale ? this.panelXY(panel, now) : c;
      set(panel.now, { x1: c[0], y1: c[1], x2: fixed(q[0]), y2: fixed(q[1]) });
      return;
    }
    var v = this.values[this.data.orders.indexOf(panel.order)][panel.quantity];
    var pair = turned(v, panel.order, theta);
    var f = panel.scale ? this.panelXY(panel, pair[0]) : c;
    var s = panel.scale ? this.panelXY(panel, { re: pair[0].re + pair[1].re, im: pair[0].im + pair[1].im }) : c;
    set(panel.forward, { x1: c[0], y1: c[1], x2: fixed(f[0]), y2: fixed(f[1]) });
    set(panel.backward, { x1: fixed(f[0]), y1: fixed(f[1]), x2: fixed(s[0]), y2: fixed(s[1]) });
    set(panel.sum, { x1: c[0], y1: c[1], x2: fixed(s[0]), y2: fixed(s[1]) });
  };

  /* --- what the controls (and a test) do ---------------------------------------------------- */

  Animation.prototype.play = function () {
    this.playing = true;
    this.last = performance.now();
    this.playButton.textContent = "❚❚ pause";
  };

  Animation.prototype.pause = function () {
    this.playing = false;
    this.playButton.textContent = "▶ play";
  };

  Animation.prototype.setSpeed = function (degreesPerSecond) {
    this.speed = degreesPerSecond;
    this.slider.value = String(degreesPerSecond);
    var real = this.data.speedRpm * 6;
    this.speedText.textContent = " " + degreesPerSecond + "°/s (1/" +
      spaced(real / degreesPerSecond) + " of " + spaced(this.data.speedRpm) + " rpm)";
  };

  /* pause, and go to the next firing top dead centre after the angle shown: its own instant */
  Animation.prototype.stepTDC = function () {
    this.pause();
    var d = this.data, from = this.drawn().angle, best = null;
    for (var i = 0; i < d.events.length; i++) {
      var ahead = ((d.events[i][0] - from) % d.cycle + d.cycle) % d.cycle;
      if (ahead < 1e-9) { ahead += d.cycle; }
      if (best === null || ahead < best.ahead - 1e-9) { best = { ahead: ahead, index: i }; }
    }
    this.event = best.index;
    this.angle = d.events[best.index][0];
    this.draw();
    var angle = this.angle;
    return {
      angle: angle,
      cylinders: d.events.filter(function (e) { return Math.abs(e[0] - angle) < 1e-9; })
        .map(function (e) { return e[1]; })
    };
  };

  /* pause at the frame nearest engine angle (degrees of the cycle) */
  Animation.prototype.seek = function (angle) {
    this.pause();
    this.event = null;
    this.angle = ((angle % this.data.cycle) + this.data.cycle) % this.data.cycle;
    this.draw();
    return this.drawn();
  };

  Animation.prototype.setOrder = function (order, on) {
    this.ordersOn[order] = !!on;
    this.orderBoxes[order].checked = !!on;
    this.rescale();
    this.draw();
  };

  /* a cylinder on or off; false (nothing changed) for a master rod's cylinder, or the last */
  Animation.prototype.setCylinder = function (number, on) {
    var group = this.data.groups.filter(function (g) { return g.cylinder === number; })[0];
    var self = this;
    var left = this.data.groups.filter(function (g) { return g.cylinder && self.on[g.cylinder]; });
    if (!group || !group.toggle || (!on && left.length === 1 && this.on[number])) { return false; }
    this.on[number] = !!on;
    this.cylinderBoxes[number].checked = !!on;
    this.compute();
    this.rescale();
    this.draw();
    return true;
  };

  /* every order's phasors with the cylinders on (N, N·m; forward and backward, [re, im]) */
  Animation.prototype.phasors = function () {
    return this.values.map(function (v) {
      return {
        order: v.order,
        force: { forward: v.force.slice(0, 2), backward: v.force.slice(2) },
        moment: { forward: v.moment.slice(0, 2), backward: v.moment.slice(2) }
      };
    });
  };

  /* the drawn instant: its engine angle, its frame (null at a firing's own instant), and
     when it was drawn (performance.now(), ms) */
  Animation.prototype.state = function () {
    var now = this.shown;
    return {
      angle: now.angle, frame: now.frame, event: now.event, playing: this.playing,
      time: this.drawnAt
    };
  };

  function mountAll() {
    var roots = document.querySelectorAll(".balance-animation");
    Array.prototype.forEach.call(roots, function (root) {
      if (root.getAttribute("data-mounted")) { return; }
      var holder = root.querySelector("script." + DATA_CLASS);
      if (!holder) { return; }
      root.setAttribute("data-mounted", "yes");
      registry.push(new Animation(root, JSON.parse(holder.textContent)));
    });
  }

  if (document.readyState === "loading") {
    document.addEventListener("DOMContentLoaded", mountAll);
  } else {
    mountAll();
  }
})();
