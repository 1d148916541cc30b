// The HTML report of `gearcoupling validate` (validation_report_html.cc inlines this file and
// Chart.js). DATA is a gearcoupling.v1.ValidationReport in protobuf JSON (proto field names).
// Moments and errors are in kN·m throughout. Charts of an input this recording does not vary
// are left out, and the report says which. Every error map shares one colour scale.
"use strict";
const R = DATA.result;
const MODELS = R.models || [];
const POINTS = DATA.plot_points || [];
const TREF = R.reference_torque_nm;
const JAM = R.jam_angle_rad;
const DEG = 180 / Math.PI;
const CHANNELS = [["msy", "M_sy'"], ["msz", "M_sz'"]];
// One colour per (model, channel); the measurement is light grey, drawn beneath the models.
const PALETTE = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"];
const colour = (m, c) => PALETTE[(2 * m + c) % PALETTE.length];
const num = (v) => (v === undefined ? NaN : Number(v));
const fmt = (v, d) => (Number.isFinite(v) ? v.toFixed(d) : "n/a");
Chart.defaults.animation = false;
Chart.defaults.font.size = 13;

function el(tag, attrs, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
  for (const c of children) e.append(c);
  return e;
}
const main = document.getElementById("main");
const section = (title, note) => {
  main.append(el("h2", {}, title));
  if (note) main.append(el("p", { class: "note" }, note));
  const grid = el("div", { class: "grid" });
  main.append(grid);
  return grid;
};
function chart(grid, title, xLabel, yLabel, datasets, type) {
  const box = el("div", { class: "chart" });
  const canvas = el("canvas");
  box.append(canvas);
  grid.append(box);
  new Chart(canvas, {
    type: type || "scatter",
    data: { datasets: datasets.datasets || datasets, labels: datasets.labels },
    options: {
      maintainAspectRatio: false,
      plugins: { title: { display: true, text: title, font: { size: 15 } },
                 legend: { position: "bottom" } },
      scales: { x: { title: { display: true, text: xLabel } },
                y: { title: { display: true, text: yLabel } } },
      elements: { point: { radius: 2 } },
    },
  });
}

// Signed misalignment in % of the jam angle: negative when beta points the other way (beta + pi),
// as the paper's Figures 10-13 draw it.
const points0 = POINTS.length ? POINTS[0].points || [] : [];
const base = (points0.find((p) => num(p.misalignment_rad) > 0) || { direction_rad: 0 }).direction_rad;
const signedMis = (p) =>
  (100 * num(p.misalignment_rad) / JAM) * (Math.cos(num(p.direction_rad) - num(base)) >= 0 ? 1 : -1);
const kNm = (v) => v / 1e3;
// An input this recording holds constant: its charts would be one vertical stripe.
const spread = (values) => {
  const finite = values.filter(Number.isFinite);
  if (finite.length < 2) return 0;
  const lo = Math.min(...finite), hi = Math.max(...finite);
  return hi - lo > 1e-9 * (Math.abs(hi) + Math.abs(lo)) ? hi - lo : 0;
};
const LEFT_OUT = [];   // "residual against direction", ... : charts without spread
const MEASURED_STYLE = { backgroundColor: "rgba(150,150,150,0.35)", pointRadius: 1.5, order: 2 };
const modelStyle = (m, c) => ({ backgroundColor: colour(m, c), borderColor: colour(m, c),
  pointStyle: "rectRot", pointRadius: 3, order: 1 });   // lower order is drawn on top

function header() {
  const names = MODELS.map((m) => m.model).join(" vs ");
  main.append(el("h1", {}, `${R.recording} against ${names}`));
  main.append(el("p", { class: "note" },
    `${R.recording_rows} rows, ${R.excluded_rows} excluded as malformed. Reference torque ` +
    `T_ref = ${fmt(TREF / 1e6, 3)} MN·m; jam angle ${fmt(JAM * DEG, 4)} deg. ` +
    `Errors are model - measurement; moments and errors in kN·m.`));
}

function metricsTable() {
  main.append(el("h2", {}, "Error per channel"));
  const t = el("table", { class: "metrics" });
  t.append(el("tr", {}, ...["model", "channel", "samples", "RMSE kN·m", "bias kN·m", "R²",
    "max |err| kN·m", "refused"].map((h) => el("th", {}, h))));
  for (const m of MODELS) {
    for (const [key, name] of CHANNELS) {
      const e = m.overall[key];
      const r2 = e.r_squared === undefined ? "n/a" : fmt(num(e.r_squared), 4);
      t.append(el("tr", {}, ...[m.model, name, num(e.count), fmt(num(e.rmse_nm) / 1e3, 2),
        fmt(num(e.bias_nm) / 1e3, 2), r2, fmt(num(e.max_abs_error_nm) / 1e3, 2),
        num(m.rejected_samples)].map((v) => el("td", {}, String(v)))));
    }
  }
  main.append(t);
}

function whereItFails() {
  main.append(el("h2", {}, "Where the model fails"));
  for (const m of MODELS) {
    main.append(el("p", {}, el("b", {}, m.model),
      " - noise and systematic error per channel, then the worst region of each input, worst " +
      "first, from a contrast (region RMSE / RMSE elsewhere) of 1.2:"));
    const list = el("ul");
    for (const sig of m.signatures || []) {
      const shares = (sig.shares || []).filter((x) => num(x.explained_share) >= 0.1)
        .sort((a, b) => num(b.explained_share) - num(a.explained_share))
        .map((x) => `${x.dimension} ${fmt(100 * num(x.explained_share), 0)} %`).join(", ");
      list.append(el("li", {}, el("b", {}, sig.channel + ": "), sig.at_noise_level
        ? `at the noise level (noise estimate ${fmt(num(sig.noise_estimate_nm) / 1e3, 2)} kN·m): no systematic error to locate.`
        : `noise ${fmt(num(sig.noise_estimate_nm) / 1e3, 2)} kN·m (+) systematic ${fmt(num(sig.systematic_rms_nm) / 1e3, 2)} kN·m; ` +
          `explained by the bins of: ${shares || "no single input"}.`));
    }
    // As the terminal: regions of channels above the noise, from a contrast of 1.2.
    const noisy = new Set((m.signatures || []).filter((x) => x.at_noise_level).map((x) => x.channel));
    for (const r of (m.worst_regions || []).filter((r) => !noisy.has(r.channel) && num(r.contrast) >= 1.2)) {
      list.append(el("li", {}, `[${fmt(num(r.contrast), 1)}x] ${r.description}`));
    }
    main.append(list);
    if (num(m.rejected_samples) > 0) {
      const refused = el("ul");
      for (const r of m.rejections) {
        refused.append(el("li", {}, `${num(r.count)} x ${r.field}: first at t = ` +
          `${fmt(num(r.first_time_s), 3)} s: ${r.first_message}`));
      }
      main.append(el("p", {}, `${num(m.rejected_samples)} samples refused by ${m.model} ` +
        "(not in the metrics):"), refused);
    }
  }
  if (num(R.excluded_rows) > 0) {
    const rows = el("ul");
    for (const p of (R.row_problems || []).slice(0, 20)) {
      rows.append(el("li", {}, `line ${num(p.line)}` +
        (num(p.column) > 0 ? `, column ${num(p.column)} (${p.column_name})` : "") + `: ${p.message}`));
    }
    main.append(el("p", {}, `${num(R.excluded_rows)} rows excluded as malformed (first ones):`), rows);
  }
}

// Measured points beneath each model's predictions: Figures 10-13's axes.
function modelVsMeasurement() {
  const grid = section("Model against measurement",
    "Bending moment at the sensors [kN·m] against the misalignment in % of the jam angle " +
    "(negative: direction turned by 180 deg), as the paper's Figures 10-11, and against torque, " +
    "as Figures 12-13. Grey: measurement; coloured diamonds, drawn on top: models. A bounded, " +
    "evenly spaced subset of the samples.");
  for (const [xName, xOf] of [["misalignment [% of jam angle]", signedMis],
                              ["torque [MN·m]", (p) => num(p.torque_nm) / 1e6]]) {
    const input = xName.split(" [")[0];
    if (!spread(points0.map(xOf))) {
      LEFT_OUT.push(`model against measurement by ${input}`);
      continue;
    }
    CHANNELS.forEach(([key, name], c) => {
      const sets = [{ label: `${name} measured`, ...MEASURED_STYLE,
        data: points0.map((p) => ({ x: xOf(p), y: kNm(num(p[key + "_nm"])) })) }];
      POINTS.forEach((mp, m) => sets.push({ label: `${name} ${mp.model}`, ...modelStyle(m, c),
        data: (mp.points || []).filter((p) => p["model_" + key + "_nm"] !== undefined)
          .map((p) => ({ x: xOf(p), y: kNm(num(p["model_" + key + "_nm"])) })) }));
      chart(grid, `${name} against ${input}`, xName, `${name} [kN·m]`, sets);
    });
  }
}

function residuals() {
  const grid = section("Residuals against each input", "Model - measurement [kN·m] of the plotted samples.");
  const inputs = [["torque [MN·m]", (p) => num(p.torque_nm) / 1e6],
    ["misalignment [% of jam angle]", (p) => 100 * num(p.misalignment_rad) / JAM],
    ["misalignment direction [deg]", (p) => num(p.direction_rad) * DEG],
    ["loading direction (-1 falling, 0 still, +1 rising)", (p) => num(p.loading_direction || 0)],
    ["time [s]", (p) => num(p.time_s)]];
  for (const [xName, xOf] of inputs) {
    const input = xName.split(" [")[0].split(" (")[0];
    if (!spread(points0.map(xOf))) {
      LEFT_OUT.push(`residual against ${input}`);
      continue;
    }
    const sets = [];
    POINTS.forEach((mp, m) => CHANNELS.forEach(([key, name], c) => sets.push({
      label: `${name} ${mp.model}`, backgroundColor: colour(m, c),
      data: (mp.points || []).filter((p) => p["model_" + key + "_nm"] !== undefined)
        .map((p) => ({ x: xOf(p), y: kNm(num(p["model_" + key + "_nm"]) - num(p[key + "_nm"])) })) })));
    chart(grid, `Residual against ${input}`, xName, "model - measurement [kN·m]", sets);
  }
}

const binLabel = (dimension, b) => {
  const lo = num(b.lower), hi = num(b.upper);
  switch (dimension) {
    case "torque": return `${fmt(lo / 1e6, 2)}-${fmt(hi / 1e6, 2)}`;
    case "misalignment": return `${fmt(100 * lo / JAM, 0)}-${fmt(100 * hi / JAM, 0)} %`;
    case "direction": return `${fmt(lo * DEG, 0)}..${fmt(hi * DEG, 0)}`;
    case "loading": return ["falling", "still", "rising"][Math.round(lo + 1.5)] || "";
    default: return `${fmt(lo, 1)}-${fmt(hi, 1)}`;
  }
};
const AXIS = { torque: "torque bin [MN·m]", misalignment: "misalignment bin [% of jam angle]",
  direction: "direction bin [deg]", loading: "loading direction", time: "time bin [s]" };

function binnedErrors() {
  const grid = section("Error by input", "RMSE (bars) of every populated bin; each bin's bias is in --json (binnings).");
  const dimensions = (MODELS[0] || { binnings: [] }).binnings.map((b) => b.dimension);
  for (const dimension of dimensions) {
    const bins0 = MODELS[0].binnings.find((b) => b.dimension === dimension).bins;
    const used = bins0.map((b, i) => i).filter((i) => num(bins0[i].errors.msy.count) > 0);
    if (used.length < 2) {
      LEFT_OUT.push(`RMSE by ${dimension}`);
      continue;
    }
    const datasets = [];
    MODELS.forEach((m, mi) => {
      const bins = m.binnings.find((b) => b.dimension === dimension).bins;
      CHANNELS.forEach(([key, name], c) => datasets.push({ label: `${name} ${m.model} RMSE`,
        backgroundColor: colour(mi, c), data: used.map((i) => num(bins[i].errors[key].rmse_nm) / 1e3) }));
    });
    chart(grid, `RMSE by ${dimension}`, AXIS[dimension], "RMSE [kN·m]",
      { labels: used.map((i) => binLabel(dimension, bins0[i])), datasets }, "bar");
  }
}

// Torque x misalignment cells coloured by RMSE on one absolute scale for every map: white at
// zero, deep red at the worst cell of all models and channels (DATA.colour_scale_max_nm), so a
// model at the noise level reads pale beside one that fails. The noise level is marked on the
// scale. The page exposes the scale in data attributes (tests/validation/report_browser_test.cc).
const SCALE_MAX = Math.max(1e-9, num(DATA.colour_scale_max_nm));
const NOISE = num(DATA.noise_level_nm) || 0;
const alphaOf = (rmse) => 0.05 + 0.85 * Math.min(1, rmse / SCALE_MAX);

function colourScale() {
  const box = el("div", { class: "scale", id: "colour-scale",
    "data-scale-max-nm": String(SCALE_MAX), "data-noise-level-nm": String(NOISE) });
  const bar = el("div", { class: "bar" });
  const noiseAt = Math.min(100, (100 * NOISE) / SCALE_MAX);
  bar.append(el("div", { class: "noise", style: `left: ${fmt(noiseAt, 2)}%`,
    title: `noise level ${fmt(NOISE / 1e3, 2)} kN·m` }));
  box.append(el("span", {}, "0"), bar, el("span", {}, `${fmt(SCALE_MAX / 1e3, 1)} kN·m`),
    el("span", { class: "note" }, ` RMSE; the black mark is the noise level, ${fmt(NOISE / 1e3, 2)} kN·m: ` +
      "a cell near it is as good as the measurement allows."));
  return box;
}

function errorMaps() {
  main.append(el("h2", {}, "Error map: torque x misalignment"));
  main.append(el("p", { class: "note" }, "RMSE [kN·m] per cell (samples in brackets); rows torque, " +
    "columns misalignment amplitude. One colour scale for every map:"));
  main.append(colourScale());
  const wrap = el("div", { class: "maps", "data-scale-max-nm": String(SCALE_MAX) });
  main.append(wrap);
  for (const m of MODELS) {
    const map = m.error_map, te = map.torque_edges_nm.map(num), me = map.misalignment_edges_rad.map(num);
    for (const [key, name] of CHANNELS) {
      const cols = me.length - 1;
      const t = el("table", { class: "map", "data-model": m.model, "data-channel": name });
      t.append(el("caption", {}, `${name}, ${m.model}`));
      t.append(el("tr", {}, el("th", {}, "T [MN·m] \\ ζ [% jam]"),
        ...me.slice(0, -1).map((lo, j) => el("th", {}, `${fmt(100 * lo / JAM, 0)}-${fmt(100 * me[j + 1] / JAM, 0)}`))));
      for (let i = te.length - 2; i >= 0; --i) {
        const row = el("tr", {}, el("th", {}, `${fmt(te[i] / 1e6, 2)}-${fmt(te[i + 1] / 1e6, 2)}`));
        for (let j = 0; j < cols; ++j) {
          const cell = map.cells[i * cols + j][key], n = num(cell.count);
          const rmse = num(cell.rmse_nm);
          const td = n > 0
            ? el("td", { style: `background: rgba(214,39,40,${fmt(alphaOf(rmse), 3)})`,
                "data-rmse-nm": String(rmse), "data-alpha": fmt(alphaOf(rmse), 3) },
                `${fmt(rmse / 1e3, 1)} (${n})`)
            : el("td", {}, "");
          row.append(td);
        }
        t.append(row);
      }
      wrap.append(t);
    }
  }
}

// What was left out and why, above the charts: a placeholder filled once they are drawn.
function leftOutNote() {
  const note = el("p", { class: "note", id: "left-out" });
  main.append(note);
  return note;
}
function fillLeftOut(note) {
  note.setAttribute("data-left-out", LEFT_OUT.join(";"));
  if (LEFT_OUT.length) {
    note.append(`Left out, as this recording holds the input constant (one vertical stripe, or ` +
      `a single bin): ${LEFT_OUT.join(", ")}.`);
  }
}

header();
metricsTable();
whereItFails();
const leftOut = leftOutNote();
modelVsMeasurement();
residuals();
binnedErrors();
errorMaps();
fillLeftOut(leftOut);
