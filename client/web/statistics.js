// The statistics panel, a <details> over the view: its summary is one line (fps, render time, the live
// accuracy estimate, frame size, how the visible mirrors were drawn); opened, it lists every statistic of
// the last frame, a row each, and plots the estimated error of recent frames against their render time.
'use strict';

window.SpeculaStatistics = (() => {
  const ms = (v) => Number(v || 0).toFixed(1);
  const percent = (share) => `${(100 * Number(share || 0)).toFixed(2)} %`;

  // Render times and live estimates of recent frames, by frame number: an estimate arrives with a later
  // frame, or alone, possibly before its own frame is drawn, so the two are joined when plotted.
  const kPlotPoints = 120;
  const history = { renderMs: new Map(), estimates: new Map() };

  const keepLast = (map, count) => {
    for (const key of map.keys()) if (map.size > count) map.delete(key); else break;
  };

  function record(frame) {
    if (!frame.reencoded) history.renderMs.set(Number(frame.number), Number(frame.renderMs || 0));
    const accuracy = frame.accuracy;
    if (accuracy && Number(accuracy.sampled)) {
      history.estimates.set(Number(accuracy.frame), { mismatch: Number(accuracy.mismatch || 0), high: Number(accuracy.high || 0) });
    }
    keepLast(history.renderMs, 4 * kPlotPoints);
    keepLast(history.estimates, kPlotPoints);
  }

  function plotPoints() {
    return [...history.estimates].filter(([number]) => history.renderMs.has(number))
      .map(([number, estimate]) => ({ renderMs: history.renderMs.get(number), ...estimate }));
  }

  // A new session numbers its frames from 1 again.
  function reset() {
    history.renderMs.clear();
    history.estimates.clear();
  }

  // "mirror error 0.31 % (≤ 0.52 %)": the window's estimate and its 95 % upper bound.
  function accuracySummary(frame) {
    const a = frame.accuracy;
    if (!a) return null;
    if (!Number(a.windowSampled)) return 'no mirror sampled';
    return `mirror error ${percent(a.windowMismatch)} (≤ ${percent(a.windowHigh)})`;
  }

  function accuracyItems(frame, accuracySamples) {
    const a = frame.accuracy;
    if (!a) return [accuracySamples === 0 ? 'off (accuracy samples 0)' : 'waiting for the first estimate'];
    const sampled = Number(a.sampled || 0);
    return [
      sampled ? `frame ${a.frame}: ${percent(a.mismatch)} of ${sampled} mirror px wrong (95 %: ${percent(a.low)} to ${percent(a.high)})`
              : `frame ${a.frame}: no mirror pixel in view`,
      `last ${a.windowFrames || 0} frames: ${percent(a.windowMismatch)} (95 %: ${percent(a.windowLow)} to ${percent(a.windowHigh)})`,
      `traced in ${ms(a.traceMs)} ms on the server's CPU`,
    ];
  }

  // Estimated error (dots, with a faint bar up to the 95 % upper bound) against render time, newest brightest.
  function plot() {
    const canvas = document.createElement('canvas');
    canvas.className = 'accuracy-plot';
    const width = 260, height = 90, ratio = window.devicePixelRatio || 1;
    canvas.width = width * ratio;
    canvas.height = height * ratio;
    canvas.setAttribute('aria-label', 'estimated mirror error of recent frames against their render time');
    const g = canvas.getContext('2d');
    g.scale(ratio, ratio);
    const left = 44, bottom = 18, top = 6, right = 8;
    const points = plotPoints();
    const maxMs = Math.max(1, ...points.map((p) => p.renderMs)) * 1.1;
    const maxShare = Math.max(0.01, ...points.map((p) => p.high)) * 1.1;
    const x = (renderMs) => left + (width - left - right) * renderMs / maxMs;
    const y = (share) => height - bottom - (height - bottom - top) * share / maxShare;
    g.fillStyle = '#999';
    g.strokeStyle = '#555';
    g.font = '10px ui-monospace, monospace';
    g.beginPath();
    g.moveTo(left, top);
    g.lineTo(left, height - bottom);
    g.lineTo(width - right, height - bottom);
    g.stroke();
    g.fillText(percent(maxShare / 1.1), 0, top + 8);
    g.fillText('0', left - 10, height - bottom);
    g.fillText(`render ${ms(maxMs / 1.1)} ms`, width - right - 100, height - 4);
    points.forEach((p, i) => {
      const alpha = 0.25 + 0.75 * (i + 1) / points.length;
      g.strokeStyle = `rgba(120, 170, 255, ${alpha * 0.4})`;
      g.beginPath();
      g.moveTo(x(p.renderMs), y(p.mismatch));
      g.lineTo(x(p.renderMs), y(p.high));
      g.stroke();
      g.fillStyle = i + 1 === points.length ? '#ffd24a' : `rgba(120, 170, 255, ${alpha})`;
      g.fillRect(x(p.renderMs) - 1.5, y(p.mismatch) - 1.5, 3, 3);
    });
    return canvas;
  }

  // How the frame's visible mirror parts found their reflections, e.g. "2 searched (crosshair), 1 ray-cast";
  // a method other than search plans no parts and is named instead.
  function planSummary(plan, { searchName, methodName }) {
    if (searchName === null) return methodName;
    if (!plan.length) return 'no mirror in view';
    const parts = new Map();
    for (const part of plan) parts.set(part.method, (parts.get(part.method) || 0) + 1);
    const named = (method) => (method === 'virtual-objects' ? `searched (${searchName})` : method);
    return [...parts].map(([method, n]) => `${n} ${named(method)}`).join(', ');
  }

  function summaryLine(frame, context) {
    const accuracy = accuracySummary(frame);
    return `${context.fps} fps · render ${ms(frame.renderMs)} ms · ${accuracy ? `${accuracy} · ` : ''}` +
           `${frame.width}×${frame.height} · ${planSummary(frame.plan || [], context)}`;
  }

  // Each row: a label and its items, which the panel wraps between, never inside unless one is wider than the panel.
  function rows(frame, { fps, latencyMs, accuracySamples }) {
    const search = frame.search || {};
    const tessellation = frame.tessellation || {};
    const plan = frame.plan || [];
    const sum = (field) => plan.reduce((total, part) => total + Number(part[field] || 0), 0);
    const withMethod = (method) => plan.filter((part) => part.method === method).length;
    return [
      ['frame', [`${frame.width}×${frame.height} ${frame.still ? 'still' : 'interactive'}` +
                 `${frame.reencoded ? ' (view unchanged: re-encoded, not rendered)' : ''}`, `number ${frame.number}`, `${fps} fps`]],
      ['input → frame', [latencyMs === null ? '–' : `${latencyMs.toFixed(0)} ms`]],
      ['accuracy', accuracyItems(frame, accuracySamples)],
      ['server', [`render ${ms(frame.renderMs)} ms`, `encode ${ms(frame.encodeMs)} ms`, `input→sent ${ms(frame.serverMs)} ms`]],
      ['passes (GPU ms)', (frame.stages || []).map((stage) => `${stage.name} ${ms(stage.ms)}`)],
      ['search', [`${search.mirrors || 0} mirrors`, `${search.searched || 0} vertices`,
                  `${Number(search.meanSteps || 0).toFixed(2)} steps (max ${search.maxSteps || 0})`, `${search.unsolved || 0} unsolved`,
                  ...(search.enlarged || search.inNoCone ? [`${search.enlarged || 0} enlarged, ${search.inNoCone || 0} in no cone`] : [])]],
      ['tessellation', tessellation.inputTriangles
        ? [`${tessellation.inputTriangles} → ${tessellation.finishedTriangles} triangles`,
           `${tessellation.midpointSearches} midpoint searches`, ...(tessellation.capped ? ['CAPPED'] : [])]
        : ['off or nothing to split']],
      ['plan', [`${plan.length} mirror parts (${withMethod('ray-cast')} ray-cast, ${withMethod('own-colour')} own colour, ` +
                `${withMethod('environment-map')} environment map, ${plan.filter((part) => part.facesAway).length} facing away)`,
                `drew ${sum('searchedObjects')} objects, ${sum('searchedVertices')} vertices`,
                `left out ${sum('culledObjects')} objects, ${sum('culledVertices')} vertices, ` +
                `${sum('belowBudgetObjects')} objects under the error budget`,
                `${sum('uncoveredRayCast')} uncovered px ray-cast`]],
      ['stream', [`${(frame.jpegBytes / 1024).toFixed(1)} KB`, `${frame.skippedFrames || 0} skipped`,
                  `scene ${(frame.sceneTimeMs / 1000).toFixed(2)} s`]],
    ];
  }

  function span(className, ...children) {
    const element = document.createElement('span');
    element.className = className;
    element.append(...children);
    return element;
  }

  // Fills `panel` (the <details> holding a <summary> and a .statistics grid) from `frame`; `context` is what
  // the page knows itself: { fps, latencyMs, methodName, searchName (null unless searching), accuracySamples }.
  function show(panel, frame, context) {
    record(frame);
    panel.querySelector('summary').textContent = summaryLine(frame, context);
    // The label's colon, the separators and the line breaks are for the panel's text (copied, read by
    // tests); the grid lays out the spans, and a line breaks only after an item's "·".
    const value = (items) => span('value', ...items.flatMap((item, i) =>
      i + 1 < items.length ? [span('item', `${item} ·`), ' '] : [span('item', item)]));
    panel.querySelector('.statistics').replaceChildren(
      ...rows(frame, context).flatMap(([label, items]) => [span('label', `${label}:`), ' ', value(items), '\n']),
      ...(plotPoints().length ? [span('label', 'error vs render time:'), ' ', span('value', plot()), '\n'] : []));
  }

  return { show, reset };
})();
