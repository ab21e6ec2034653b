// The statistics panel, a <details> over the view: its summary is one line (fps, render time, frame
// size, how the visible mirrors were drawn); opened, it lists every statistic of the last frame, a row each.
'use strict';

window.SpeculaStatistics = (() => {
  const ms = (v) => Number(v || 0).toFixed(1);

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
    return `${context.fps} fps · render ${ms(frame.renderMs)} ms · ${frame.width}×${frame.height} · ` +
           planSummary(frame.plan || [], context);
  }

  // Each row: a label and its items, which the panel wraps between, never inside unless one is wider than the panel.
  function rows(frame, { fps, latencyMs }) {
    const search = frame.search || {};
    const tessellation = frame.tessellation || {};
    const plan = frame.plan || [];
    const sum = (field) => plan.reduce((total, part) => total + Number(part[field] || 0), 0);
    const withMethod = (method) => plan.filter((part) => part.method === method).length;
    return [
      ['frame', [`${frame.width}×${frame.height} ${frame.still ? 'still' : 'interactive'}` +
                 `${frame.reencoded ? ' (view unchanged: re-encoded, not rendered)' : ''}`, `number ${frame.number}`, `${fps} fps`]],
      ['input → frame', [latencyMs === null ? '–' : `${latencyMs.toFixed(0)} ms`]],
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

  // Fills `panel` (the <details> holding a <summary> and a .statistics grid) from `frame`;
  // `context` is what the page knows itself: { fps, latencyMs, methodName, searchName (null unless searching) }.
  function show(panel, frame, context) {
    panel.querySelector('summary').textContent = summaryLine(frame, context);
    // The label's colon, the separators and the line breaks are for the panel's text (copied, read by
    // tests); the grid lays out the spans, and a line breaks only after an item's "·".
    const value = (items) => span('value', ...items.flatMap((item, i) =>
      i + 1 < items.length ? [span('item', `${item} ·`), ' '] : [span('item', item)]));
    panel.querySelector('.statistics').replaceChildren(
      ...rows(frame, context).flatMap(([label, items]) => [span('label', `${label}:`), ' ', value(items), '\n']));
  }

  return { show };
})();
