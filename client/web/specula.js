// Specula browser client: plain JavaScript, no build step. Speaks specula.v1.json (proto3 JSON of
// proto/specula.proto) over the server's /ws WebSocket, draws the JPEG frames on a canvas and turns
// mouse, touch and keys into camera updates.
'use strict';

(() => {
  const params = new URLSearchParams(location.search);
  const canvas = document.getElementById('frame');
  const context2d = canvas.getContext('2d');
  const overlay = document.getElementById('overlay');
  const status = document.getElementById('status');
  const $ = (id) => document.getElementById(id);

  // Everything the page knows; exposed as window.specula for tests and curious users.
  const state = {
    socket: null,
    welcome: null,
    limits: { max_width: 3840, max_height: 2160 },
    camera: null,          // { target: [x,y,z], up: [x,y,z], yaw, pitch, radius, fov } once known
    cameraOwned: false,    // true once this page has sent a camera: the scene's camera no longer drives it
    sequence: 0,
    sentAt: new Map(),     // sequence → performance.now() when sent, for input-to-frame latency
    frame: null,           // the last frame drawn (without its JPEG), with the newest accuracy estimate
    accuracy: null,        // the newest live accuracy estimate (AccuracyEstimate)
    framesDrawn: 0,
    frameTimes: [],        // performance.now() of recent frames, for fps
    latencyMs: null,
    playing: true,
    resumeToken: sessionStorage.getItem('specula.resume') || '',
    reconnectDelayMs: 500,
    reconnectAttempt: 0,   // tries since the connection was lost; 0 while connected
    reconnects: 0,         // connections lost and won back
    decoding: false,
    pendingFrame: null,
    bitmap: null,          // the last decoded frame, redrawn when the canvas is resized
  };
  window.specula = state;

  // ---- status line ----
  function showStatus(text, kind = 'error') {
    status.textContent = text;
    status.className = text ? `visible ${kind}` : '';
  }

  // ---- connection ----
  function socketUrl() {
    const token = params.get('token');
    return `${location.protocol === 'https:' ? 'wss' : 'ws'}://${location.host}/ws${token ? `?token=${encodeURIComponent(token)}` : ''}`;
  }

  function send(message) {
    if (state.socket && state.socket.readyState === WebSocket.OPEN) state.socket.send(JSON.stringify(message));
  }

  function nextInput() {
    const sequence = ++state.sequence;
    const now = performance.now();
    state.sentAt.set(sequence, now);
    if (state.sentAt.size > 512) state.sentAt.delete(state.sentAt.keys().next().value);
    return { sequence, clientTimeMs: now };
  }

  function connect() {
    const socket = new WebSocket(socketUrl(), ['specula.v1.json']);
    state.socket = socket;
    socket.onopen = () => {
      const [width, height] = viewportSize();
      const hello = { protocolVersion: 1, width, height };  // the session's settings come with the Welcome
      if (state.resumeToken) hello.resumeToken = state.resumeToken;
      send({ hello });
    };
    socket.onmessage = (event) => {
      let message;
      try { message = JSON.parse(event.data); } catch (e) { showStatus(`unreadable message from the server: ${e}`); return; }
      if (message.welcome) onWelcome(message.welcome);
      else if (message.frame) onFrame(message.frame);
      else if (message.accuracy) onAccuracy(message.accuracy);
      else if (message.error?.code === 'RESUME_REFUSED') showStatus(`Reconnected as a fresh session: ${message.error.message}`, 'info');
      else if (message.error) showStatus(`server: ${message.error.message} (${message.error.code})`);
    };
    socket.onclose = (event) => onClose(event);
  }

  const closeExplanations = {
    1001: 'the server is shutting down',
    1006: 'the connection was lost',
    1007: 'the server could not read a message from this page',
    1008: 'the server refused a message from this page',
    1009: 'a message from this page was too large',
    1013: 'the server is full',
  };

  // Tries per loss, with the delay doubling from 0.5 s to 8 s: about a minute before giving up.
  const kMaxReconnectAttempts = 10;

  function onClose(event) {
    const why = closeExplanations[event.code] || `closed (${event.code})`;
    const reason = event.reason ? `: ${event.reason}` : '';
    const retry = [1001, 1006, 1011, 1012, 1013].includes(event.code);
    if (!retry) {
      showStatus(`Disconnected — ${why}${reason}. Reload the page to start again.`);
      return;
    }
    if (state.reconnectAttempt >= kMaxReconnectAttempts) {
      showStatus(`Disconnected — ${why}${reason}. Gave up after ${kMaxReconnectAttempts} attempts; reload the page to try again.`);
      return;
    }
    const delay = state.reconnectDelayMs;
    state.reconnectDelayMs = Math.min(8000, delay * 2);
    state.reconnectAttempt++;
    showStatus(`Disconnected — ${why}${reason}. Reconnecting (attempt ${state.reconnectAttempt} of ${kMaxReconnectAttempts}) ` +
               `in ${(delay / 1000).toFixed(1)} s${state.resumeToken ? ', to resume this view' : ''}…`, 'info');
    setTimeout(connect, delay);
  }

  // ---- camera ----
  const toVec = (v) => [v?.x || 0, v?.y || 0, v?.z || 0];
  const toProto = (a) => ({ x: a[0], y: a[1], z: a[2] });
  const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
  const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
  const scale = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const length = (a) => Math.hypot(a[0], a[1], a[2]);
  const normalize = (a) => scale(a, 1 / (length(a) || 1));

  // Orbit parameters around the target from a protocol camera (eye, target, up, fov).
  function orbitFrom(camera) {
    const eye = toVec(camera.eye), target = toVec(camera.target);
    const offset = sub(eye, target);
    const radius = Math.max(1e-3, length(offset));
    return {
      target, up: [0, 1, 0], radius, fov: camera.fovDegrees || 45,
      yaw: Math.atan2(offset[0], offset[2]),
      pitch: Math.asin(Math.max(-1, Math.min(1, offset[1] / radius))),
    };
  }

  function eyeOf(orbit) {
    const c = Math.cos(orbit.pitch);
    return add(orbit.target, scale([c * Math.sin(orbit.yaw), Math.sin(orbit.pitch), c * Math.cos(orbit.yaw)], orbit.radius));
  }

  let cameraDirty = false;
  function changeCamera(change) {
    if (!state.camera) return;
    change(state.camera);
    state.camera.pitch = Math.max(-1.55, Math.min(1.55, state.camera.pitch));
    state.camera.radius = Math.max(1e-3, Math.min(1e5, state.camera.radius));
    state.cameraOwned = true;
    if (!cameraDirty) {
      cameraDirty = true;
      requestAnimationFrame(flushCamera);  // at most one update per display frame
    }
  }

  function flushCamera() {
    cameraDirty = false;
    const c = state.camera;
    send({ camera: { eye: toProto(eyeOf(c)), target: toProto(c.target), up: toProto(c.up), fovDegrees: c.fov, ...nextInput() } });
  }

  function orbitBy(dx, dy) { changeCamera((c) => { c.yaw -= dx * 0.008; c.pitch += dy * 0.008; }); }
  function zoomBy(factor) { changeCamera((c) => { c.radius *= factor; }); }
  function panBy(dx, dy) {
    changeCamera((c) => {
      const forward = normalize(sub(c.target, eyeOf(c)));
      const right = normalize(cross(forward, c.up));
      const up = cross(right, forward);
      const perPixel = (2 * c.radius * Math.tan((c.fov * Math.PI) / 360)) / Math.max(1, canvas.clientHeight);
      c.target = add(c.target, add(scale(right, -dx * perPixel), scale(up, dy * perPixel)));
    });
  }

  // ---- pointer, wheel and keys ----
  const pointers = new Map();
  canvas.addEventListener('pointerdown', (e) => {
    canvas.setPointerCapture(e.pointerId);
    pointers.set(e.pointerId, { x: e.clientX, y: e.clientY, pan: e.button === 2 || e.shiftKey });
    canvas.focus();
  });
  canvas.addEventListener('pointermove', (e) => {
    const last = pointers.get(e.pointerId);
    if (!last) return;
    const dx = e.clientX - last.x, dy = e.clientY - last.y;
    if (pointers.size === 2) {
      const [a, b] = [...pointers.values()];
      const other = a === last ? b : a;
      const before = Math.hypot(last.x - other.x, last.y - other.y);
      const after = Math.hypot(e.clientX - other.x, e.clientY - other.y);
      if (before > 0 && after > 0) zoomBy(before / after);
      panBy(dx / 2, dy / 2);
    } else if (last.pan) {
      panBy(dx, dy);
    } else {
      orbitBy(dx, dy);
    }
    last.x = e.clientX;
    last.y = e.clientY;
  });
  const release = (e) => pointers.delete(e.pointerId);
  canvas.addEventListener('pointerup', release);
  canvas.addEventListener('pointercancel', release);
  canvas.addEventListener('contextmenu', (e) => e.preventDefault());
  canvas.addEventListener('wheel', (e) => { e.preventDefault(); zoomBy(Math.exp(e.deltaY * 0.001)); }, { passive: false });
  document.addEventListener('keydown', (e) => {
    if (e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement) return;
    const keys = {
      ArrowLeft: () => orbitBy(-20, 0), ArrowRight: () => orbitBy(20, 0),
      ArrowUp: () => orbitBy(0, -20), ArrowDown: () => orbitBy(0, 20),
      '+': () => zoomBy(0.9), '=': () => zoomBy(0.9), '-': () => zoomBy(1.1),
      ' ': () => togglePlay(),
      o: () => { overlay.hidden = !overlay.hidden; },
      r: () => { if (state.welcome) { state.camera = orbitFrom(state.welcome.camera); changeCamera(() => {}); } },
    };
    const action = keys[e.key];
    if (action) { e.preventDefault(); action(); }
  });

  // ---- animation and settings controls ----
  function animation(fields) { send({ animation: { ...fields, ...nextInput() } }); }
  function togglePlay() {
    state.playing = !state.playing;
    animation({ action: state.playing ? 'PLAY' : 'PAUSE' });
    $('play').textContent = state.playing ? 'Pause' : 'Play';
  }
  $('play').addEventListener('click', togglePlay);
  let scrubbing = false;
  $('scrub').addEventListener('input', () => { scrubbing = true; animation({ action: 'SEEK', timeMs: Number($('scrub').value) }); });
  $('scrub').addEventListener('change', () => { scrubbing = false; });
  $('speed').addEventListener('change', () => animation({ speed: Number($('speed').value) }));

  function showSettings(settings) { if (settings) SpeculaSettings.show(settings); }

  // ---- viewport ----
  function viewportSize() {
    const ratio = window.devicePixelRatio || 1;
    const width = Math.round(Math.max(1, canvas.clientWidth) * ratio);
    const height = Math.round(Math.max(1, canvas.clientHeight) * ratio);
    return [Math.min(width, state.limits.max_width), Math.min(height, state.limits.max_height)];
  }
  let resizeTimer = 0;
  new ResizeObserver(() => {
    clearTimeout(resizeTimer);
    resizeTimer = setTimeout(() => {
      const [width, height] = viewportSize();
      if (width === canvas.width && height === canvas.height) return;
      canvas.width = width;
      canvas.height = height;
      redraw();  // resizing clears the canvas: show the last frame stretched until the new one comes
      send({ resize: { width, height, ...nextInput() } });
    }, 100);
  }).observe(canvas);

  // ---- server messages ----
  function onWelcome(welcome) {
    state.accuracy = null;  // estimates name frames of the previous connection's numbering
    SpeculaStatistics.reset();
    state.welcome = welcome;
    state.reconnectDelayMs = 500;
    if (state.reconnectAttempt > 0) state.reconnects++;
    state.reconnectAttempt = 0;
    state.limits = { max_width: welcome.limits.maxWidth, max_height: welcome.limits.maxHeight };
    keepResumeToken(welcome.resumeToken);
    state.playing = welcome.playing;
    $('play').textContent = state.playing ? 'Pause' : 'Play';
    showSettings(welcome.settings);
    if (!state.camera) state.camera = orbitFrom(welcome.camera);
    [canvas.width, canvas.height] = viewportSize();
    redraw();
    // What the scene's files hold that the server left out or read differently (notes), until dismissed by the next status.
    const notes = welcome.scene.notes || [];
    showStatus(welcome.resumed ? 'Reconnected: camera, animation and settings restored.'
      : notes.length ? `Scene notes: ${notes.join('; ')}` : '', 'info');
    if (welcome.resumed) setTimeout(() => showStatus(''), 2000);
    else applyLinkParameters();
  }

  // ?eye=x,y,z&target=x,y,z&up=x,y,z&fov=deg&time=ms&paused=1 opens a given view (shareable links, tests).
  function applyLinkParameters() {
    const vector = (name) => params.get(name)?.split(',').map(Number);
    if (params.has('eye')) {
      const camera = { eye: toProto(vector('eye')), target: toProto(vector('target') || [0, 0, 0]),
                       fovDegrees: Number(params.get('fov')) || state.camera.fov };
      state.camera = orbitFrom(camera);
      if (params.has('up')) state.camera.up = vector('up');
      changeCamera(() => {});
    }
    if (params.has('paused')) { state.playing = false; animation({ action: 'PAUSE' }); $('play').textContent = 'Play'; }
    if (params.has('time')) animation({ action: 'SEEK', timeMs: Number(params.get('time')) });
  }

  // The token that brings this view back after a reconnect, here or (stateless resume) on any instance.
  function keepResumeToken(token) {
    if (!token || token === state.resumeToken) return;
    state.resumeToken = token;
    sessionStorage.setItem('specula.resume', token);
  }

  function onFrame(frame) {
    keepResumeToken(frame.resumeToken);
    if (state.decoding) { state.pendingFrame = frame; return; }  // latest wins while one decodes
    state.decoding = true;
    const bytes = Uint8Array.from(atob(frame.jpeg), (c) => c.charCodeAt(0));
    createImageBitmap(new Blob([bytes], { type: 'image/jpeg' }))
      .then((bitmap) => {
        state.bitmap?.close();
        state.bitmap = bitmap;
        redraw();
        frameDrawn(frame, bytes.length);
      })
      .catch((e) => showStatus(`a frame could not be decoded: ${e}`))
      .finally(() => {
        state.decoding = false;
        const next = state.pendingFrame;
        state.pendingFrame = null;
        if (next) onFrame(next);
      });
  }

  // The newest live accuracy estimate, whether a frame carried it or it came alone for the frame on
  // screen (a still view); it may arrive while that frame is still being decoded.
  function noteAccuracy(accuracy) {
    if (accuracy && (!state.accuracy || Number(accuracy.frame) > Number(state.accuracy.frame))) state.accuracy = accuracy;
  }

  function onAccuracy(accuracy) {
    noteAccuracy(accuracy);
    if (!state.frame) return;
    state.frame = { ...state.frame, accuracy: state.accuracy };
    updateOverlay();
  }

  function redraw() {
    if (state.bitmap) context2d.drawImage(state.bitmap, 0, 0, canvas.width, canvas.height);
  }

  function frameDrawn(frame, jpegBytes) {
    const now = performance.now();
    const sequence = Number(frame.inputSequence);
    if (state.sentAt.has(sequence)) {
      state.latencyMs = now - state.sentAt.get(sequence);
      state.sentAt.delete(sequence);
    }
    if (!state.cameraOwned && frame.camera) state.camera = orbitFrom(frame.camera);  // follow the scene's camera
    state.frameTimes.push(now);
    while (state.frameTimes.length && now - state.frameTimes[0] > 1000) state.frameTimes.shift();
    const { jpeg, ...described } = frame;
    if (frame.settings) state.accuracy = null;  // the server starts a new window under new settings
    noteAccuracy(frame.accuracy);
    state.frame = { ...described, jpegBytes, accuracy: state.accuracy };
    showSettings(frame.settings);  // after a settings change: what the server runs, with what it implied
    state.framesDrawn++;
    if (!scrubbing) $('scrub').value = String(frame.sceneTimeMs % Number($('scrub').max));
    $('time').textContent = `${(frame.sceneTimeMs / 1000).toFixed(2)} s`;
    updateOverlay();
  }

  const optionText = (id) => $(id)?.selectedOptions[0]?.textContent ?? '';

  function updateOverlay() {
    if (!state.frame) return;
    const searching = $('method')?.value === 'SEARCH';
    SpeculaStatistics.show(overlay, state.frame, {
      fps: state.frameTimes.length, latencyMs: state.latencyMs, methodName: SpeculaSettings.describe('method'),
      searchName: searching ? optionText('search') : null, accuracySamples: Number($('accuracySamples')?.value ?? NaN),
    });
  }

  if (!('WebSocket' in window) || !('createImageBitmap' in window)) {
    showStatus('This browser lacks WebSocket or createImageBitmap; use a current Chrome, Firefox or Safari.');
  } else {
    // The settings panel first, so the Welcome's settings have controls to show them in.
    const token = params.get('token');
    fetch(`settings-schema.json${token ? `?token=${encodeURIComponent(token)}` : ''}`)
      .then((response) => (response.ok ? response.json() : Promise.reject(new Error(`HTTP ${response.status}`))))
      .then((schema) => SpeculaSettings.build($('settings'), schema, {
        send: (update) => send({ settings: { ...update, ...nextInput() } }),
        refuse: (problem) => showStatus(problem),
      }))
      .catch((error) => showStatus(`No settings panel: the server's settings schema did not load (${error.message}).`))
      .finally(connect);
  }
})();
