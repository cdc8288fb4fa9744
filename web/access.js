// access.js — the page's parallel DOM: the lab as native HTML controls that a screen reader reads
// and the keyboard drives, built from the lab's own description of itself (app/page_model.h:
// the field table's rows, the command table's buttons, the pictures in words).
//
// The DOM is not drawn, except the control that has the keyboard: it shows as a card at the
// bottom of the page, and its widget on the canvas gets a focus ring (lab_page_focus). A change
// goes to the lab as the panel's own would (lab_page_field, lab_page_command: one undo step each);
// a change on the canvas comes back in the next description. Key events aimed at these controls
// never reach Emscripten's GLFW (index.html), so typing here fires no shortcut.
'use strict';
(function () {
  // Off only for the browser benchmark's baseline (web/bench/drag-frame.bench.mjs): a drag's frame without the parallel DOM.
  if (window.labParallelDom === false) return;
  const root = document.getElementById('lab-access');
  const tabs = document.getElementById('lab-tabs');
  const panels = document.getElementById('lab-panels');
  const log = document.getElementById('lab-log');
  let shape = '';      // the structure last built (the description without its values)
  let model = null;    // the last description
  let describedAt = 0; // when the pictures' words were last put into the page
  let pendingWords = null;
  let lastScore = '';
  let chosenTab = 'material';
  const units = { deg: 'degrees', 'deg/s': 'degrees per second' };
  const parts = { color: ['red', 'green', 'blue'], int2: ['first', 'second'] };

  const el = (tag, attrs = {}, ...children) => {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs)) {
      if (v === undefined || v === null || v === false) continue;
      if (k === 'text') e.textContent = v;
      else if (k.startsWith('on')) e.addEventListener(k.substring(2), v);
      else e.setAttribute(k, v === true ? '' : v);
    }
    for (const c of children) if (c) e.append(c);
    return e;
  };
  const idOf = (path) => 'f-' + path.replace(/[^a-z0-9_]/gi, '_');
  // A field's new value to the lab (web_window.cpp labJsFieldSender: any text, NULs and megabytes
  // included); the control's last refusal goes, and comes back if the lab refuses this one too.
  const send = (path, value) => {
    refusal(path, '');
    Module.labPageField(path, String(value));
  };
  const command = (b) => Module._lab_page_command(b.command, b.index === undefined ? -1 : b.index);
  const focusPath = (path) => Module.ccall('lab_page_focus', null, ['string'], [path]);
  const labelOf = (c) => c.label + (c.unit ? ' (' + c.unit + ')' : '');
  const spoken = (v, c) => {
    const n = typeof v === 'number' ? Number(v.toFixed(4)) : v;
    return c.unit ? n + ' ' + (units[c.unit] || c.unit) : String(n);
  };

  // One number: a slider where the table's slider spans its whole range, else a text field that is a
  // spin button (Up and Down step it, spinKey). Not <input type=number>: the browser keeps to itself
  // what it cannot read ("1e309", "-", "--5" leave its value empty), so nothing reached the lab and
  // nobody heard why. Here every text goes to the lab, which reads it as a preset file's number and
  // says why it refuses one, in the message log and in the field's description (WCAG 3.3.1).
  function numberInput(c, path, name, value) {
    const common = { id: idOf(path), 'data-path': path, 'aria-label': name,
      'aria-describedby': c.help ? idOf(c.path) + '-help' : null };
    const input = c.slider
      ? el('input', { type: 'range', min: c.min, max: c.max, step: c.step, ...common })
      : el('input', { type: 'text', role: 'spinbutton', inputmode: c.min < 0 ? 'text' : 'decimal', autocomplete: 'off',
        spellcheck: 'false', 'aria-valuemin': c.min, 'aria-valuemax': c.max, 'data-step': c.step, ...common });
    shownValue(input, value, c);
    // The lab checks the range and says what is wrong (a value off the step's grid is taken).
    input.addEventListener(c.slider ? 'input' : 'change', () => send(path, input.value));
    return input;
  }

  // The lab's value in a number control: the text, and a spin button's value for a screen reader.
  function shownValue(input, v, c) {
    if (input.value !== String(v)) input.value = v;
    input.setAttribute('aria-valuetext', spoken(v, c));
    if (input.type !== 'range') input.setAttribute('aria-valuenow', v);
  }

  // Up and Down on a number field: one step (PageUp and PageDown ten) from the lab's value, within
  // the field's range, as a native spin button does.
  function spinKey(e) {
    const steps = { ArrowUp: 1, ArrowDown: -1, PageUp: 10, PageDown: -10 }[e.key];
    if (steps === undefined || e.altKey || e.ctrlKey || e.metaKey) return false;
    const input = e.target, now = Number(input.getAttribute('aria-valuenow'));
    const min = Number(input.getAttribute('aria-valuemin')), max = Number(input.getAttribute('aria-valuemax'));
    const next = Math.min(max, Math.max(min, Number((now + steps * Number(input.dataset.step)).toPrecision(12))));
    input.value = next;
    send(input.dataset.path, String(next));
    return true;
  }

  // Why the lab refused the text of the control at `path` ("" clears it): said beside the control, which
  // is marked invalid and described by it, until the next value it sends.
  function refusal(path, message) {
    const input = root.querySelector(`[data-path="${CSS.escape(path)}"]:not([type=radio])`);
    if (!input) return;
    const id = idOf(path) + '-error';
    let note = document.getElementById(id);
    const described = (input.getAttribute('aria-describedby') || '').split(' ').filter((d) => d && d !== id);
    if (!message) {
      if (note) note.remove();
      input.removeAttribute('aria-invalid');
    } else {
      if (!note) {
        note = el('span', { id, class: 'error' });
        input.after(note);
      }
      note.textContent = message;
      input.setAttribute('aria-invalid', 'true');
      described.push(id);
    }
    if (described.length) input.setAttribute('aria-describedby', described.join(' '));
    else input.removeAttribute('aria-describedby');
  }

  function control(c) {
    const help = c.help ? el('span', { id: idOf(c.path) + '-help', class: 'help', text: c.help }) : null;
    const row = el('div', { class: 'row', 'data-key': c.path });
    if (c.kind === 'number') {
      const input = numberInput(c, c.path, labelOf(c), c.value);
      input.removeAttribute('aria-label');
      row.append(el('label', { for: input.id, text: labelOf(c) }), input, help);
    } else if (c.kind === 'switch') {
      const input = el('input', { type: 'checkbox', id: idOf(c.path), 'data-path': c.path,
        'aria-describedby': help ? help.id : null, onchange: (e) => send(c.path, e.target.checked) });
      input.checked = c.value;
      row.append(input, el('label', { for: input.id, text: labelOf(c) }), help);
    } else if (c.kind === 'choice' && c.radios) {
      const group = el('fieldset', { 'aria-describedby': help ? help.id : null }, el('legend', { text: labelOf(c) }));
      for (const choice of c.choices) {
        const id = idOf(c.path) + '-' + choice.name;
        const radio = el('input', { type: 'radio', id, name: idOf(c.path), value: choice.name, 'data-path': c.path,
          onchange: () => send(c.path, choice.name) });
        radio.checked = c.value === choice.name;
        group.append(el('span', { class: 'choice' }, radio, el('label', { for: id, text: choice.label })));
      }
      row.append(group, help);
    } else if (c.kind === 'choice') {
      const select = el('select', { id: idOf(c.path), 'data-path': c.path, 'aria-describedby': help ? help.id : null,
        onchange: (e) => send(c.path, e.target.value) });
      for (const choice of c.choices) select.append(el('option', { value: choice.name, text: choice.label }));
      select.value = c.value;
      row.append(el('label', { for: select.id, text: labelOf(c) }), select, help);
    } else if (c.kind === 'text' || c.kind === 'code') { // a text field; a shader's source in a text area
      const input = el(c.kind === 'code' ? 'textarea' : 'input', { type: c.kind === 'code' ? null : 'text', id: idOf(c.path),
        'data-path': c.path, 'aria-describedby': help ? help.id : null, spellcheck: 'false',
        onchange: (e) => send(c.path, e.target.value) });
      input.value = c.value;
      row.append(el('label', { for: input.id, text: labelOf(c) }), input, help);
    } else { // a triplet or a pair: one number each, in a group named by the field
      const names = parts[c.kind] || ['x', 'y', 'z'];
      const group = el('fieldset', { 'aria-describedby': help ? help.id : null }, el('legend', { text: labelOf(c) }));
      c.value.forEach((v, i) => {
        const path = c.path + '[' + i + ']';
        group.append(numberInput(c, path, labelOf(c) + ' ' + names[i], v));
      });
      row.append(group, help);
    }
    return row;
  }

  function button(b) {
    const label = b.label + (b.keys ? ' (' + b.keys + ')' : '');
    return el('button', { type: 'button', 'data-key': 'command-' + b.command + '-' + (b.index ?? -1),
      'aria-current': b.current ? 'true' : null, 'aria-keyshortcuts': b.keys ? b.keys.replace(/\s/g, '') : null,
      'aria-pressed': b.pressed === undefined ? null : String(b.pressed),
      text: b.label, 'aria-label': b.keys ? label : null, onclick: () => command(b) });
  }

  function section(s) {
    const heading = el('h3', { id: 'h-' + s.id, text: s.label });
    const box = el('section', { class: 'section', 'aria-labelledby': heading.id }, heading);
    for (const c of s.controls) box.append(control(c));
    if (s.buttons.length) {
      const group = el('div', { class: 'buttons', role: 'group', 'aria-label': s.label });
      for (const b of s.buttons) group.append(button(b));
      box.append(group);
    }
    // The shader editor's compile log or the sweep's problem; the QR code's link while it is shown.
    if (s.log) box.append(el('pre', { class: 'log', role: 'status', text: s.log }));
    if (s.link && s.linkProblem) {
      box.append(el('p', { role: 'status' }, 'No QR code: ' + s.linkProblem + ' The link: ', el('a', { href: s.link, text: s.link })));
    } else if (s.link) {
      box.append(el('p', {}, 'The QR code opens ', el('a', { href: s.link, text: s.link })));
    }
    return box;
  }

  // The page's theme: the lab's two, chosen here as in the lab's panel (and remembered as a choice).
  function themeControl() {
    const select = el('select', { id: 'lab-theme', 'data-key': 'theme', onchange: (e) => {
      labThemeChosen(e.target.value);
      Module.ccall('lab_set_theme', null, ['string'], [e.target.value]);
    } }, el('option', { value: 'dark', text: 'dark' }), el('option', { value: 'light', text: 'light (a projector in a lit room)' }));
    return el('div', { class: 'row', 'data-key': 'theme' }, el('label', { for: 'lab-theme', text: 'Theme' }), select);
  }

  // The compact layout's tabs as a tablist: arrows move between tabs, and each tab is a Tab stop too (so
  // that Tab alone reaches every control: Tab to a tab, Enter or Space opens it, Tab into it).
  function selectTab(id, focus) {
    chosenTab = id;
    for (const t of tabs.querySelectorAll('[role=tab]')) {
      const on = t.dataset.tab === id;
      t.setAttribute('aria-selected', on);
      t.tabIndex = 0;
      if (on && focus) t.focus();
    }
    for (const p of panels.children) p.hidden = p.dataset.tab !== id;
  }
  function tabKey(e) {
    const all = [...tabs.querySelectorAll('[role=tab]')];
    const at = all.indexOf(e.target);
    const to = { ArrowRight: at + 1, ArrowLeft: at - 1, Home: 0, End: all.length - 1 }[e.key];
    if (at < 0 || to === undefined) return false;
    selectTab(all[(to + all.length) % all.length].dataset.tab, true);
    return true;
  }

  function exercise(e) {
    const box = document.getElementById('lab-exercise');
    box.hidden = !e;
    if (!e) return;
    box.replaceChildren(el('h2', { id: 'h-exercise', text: 'Exercise: ' + e.title }), el('p', { text: e.instructions }),
      ...e.hints.map((h, i) => el('p', { text: 'Hint ' + (i + 1) + ': ' + h })),
      el('p', { id: 'lab-score', role: 'status', text: e.score ? e.score : 'Not scored yet' }),
      el('div', { class: 'buttons', role: 'group', 'aria-label': 'Exercise' }, ...e.buttons.map(button)));
  }

  function build(m) {
    const focused = document.activeElement && root.contains(document.activeElement) ?
      (document.activeElement.closest('[data-key]') || {}).dataset : null;
    const focusedId = document.activeElement ? document.activeElement.id : '';
    tabs.replaceChildren();
    panels.replaceChildren();
    for (const t of m.tabs) {
      tabs.append(el('button', { type: 'button', role: 'tab', id: 'tab-' + t.id, 'data-tab': t.id,
        'aria-controls': 'panel-' + t.id, text: t.label, onclick: () => selectTab(t.id, true) }));
      const panel = el('div', { role: 'tabpanel', id: 'panel-' + t.id, 'data-tab': t.id, 'aria-labelledby': 'tab-' + t.id });
      for (const s of m.sections.filter((s) => s.tab === t.id)) panel.append(section(s));
    if (t.id === 'model') panel.append(themeControl());
      panels.append(panel);
    }
    selectTab(m.tabs.some((t) => t.id === chosenTab) ? chosenTab : m.tabs[0].id, false);
    const again = (focusedId && document.getElementById(focusedId)) ||
      (focused && focused.key && root.querySelector(`[data-key="${CSS.escape(focused.key)}"] input, [data-key="${CSS.escape(focused.key)}"]`));
    if (again && again.focus) again.focus({ preventScroll: true });
  }

  // The values of a description whose structure is the one built.
  function update(m) {
    for (const s of m.sections) {
      for (const c of s.controls) {
        const values = Array.isArray(c.value) ? c.value : [c.value];
        values.forEach((v, i) => {
          const path = Array.isArray(c.value) ? c.path + '[' + i + ']' : c.path;
          for (const input of root.querySelectorAll(`[data-path="${CSS.escape(path)}"]`)) {
            const editing = input === document.activeElement && ['text', 'textarea'].includes(input.type);
            if (input.type === 'radio') input.checked = input.value === v;
            else if (input.type === 'checkbox') input.checked = v;
            else if (typeof v === 'number') {
              if (!editing) shownValue(input, v, c);
              else input.setAttribute('aria-valuenow', v); // what is typed stays while it is edited
            } else if (!editing && input.value !== String(v)) input.value = v;
          }
        });
      }
      for (const b of s.buttons) {
        const e = root.querySelector(`[data-key="command-${b.command}-${b.index ?? -1}"]`);
        if (e && b.index !== undefined) e.setAttribute('aria-current', b.current ? 'true' : 'false');
        if (e && b.pressed !== undefined) e.setAttribute('aria-pressed', String(b.pressed));
      }
    }
  }

  function words(p) {
    document.getElementById('lab-description').textContent = p.description;
    document.getElementById('lab-plot-summary').textContent = p.plot.summary;
    const body = document.getElementById('lab-plot-rows');
    body.replaceChildren(...p.plot.rows.map((r) => el('tr', {}, el('th', { scope: 'row', text: r[0] + '°' }),
      ...r.slice(1).map((v) => el('td', { text: v.toFixed(3) })))));
    document.getElementById('lab-lobe').textContent = p.lobe;
    document.getElementById('lab-slice').textContent = p.slice;
    describedAt = performance.now();
  }

  function messages(m) {
    const say = (text) => {
      log.append(el('p', { text: new Date().toLocaleTimeString() + ': ' + text }));
      while (log.children.length > 30) log.firstElementChild.remove();
    };
    for (const text of m.messages.said) say(text); // every message since the last description, even a brief one
    for (const r of m.messages.refused) refusal(r.path, r.message); // and beside each control it refused
    const score = m.exercise ? m.exercise.score : '';
    if (score && score !== lastScore && m.exercise.solved) say('Solved: ' + m.exercise.title);
    lastScore = score;
    document.getElementById('lab-probe').textContent = m.readouts.probe || 'No pixel probed yet (click the model).';
    document.getElementById('lab-legend').textContent = m.readouts.legend || 'The lit model is shown.';
  }

  // The dialog the canvas shows (an error, unsaved changes), as an alertdialog with its buttons:
  // the focus goes into it, to its first (default) button, and back where it was once answered.
  // (Its keys never reach the canvas: index.html stops them, and hands them to labAccessKey.)
  const box = document.getElementById('lab-dialog');
  let dialogReturn = null;
  // Esc in it answers its last button (Cancel, or OK), as on the canvas; Enter is its focused button's.
  const dialogKey = (e) => {
    if (e.key !== 'Escape' || !box.contains(e.target)) return false;
    const last = box.querySelector('button:last-of-type');
    if (last) last.click();
    return true;
  };
  function dialog(d) {
    const key = d ? JSON.stringify(d) : '';
    if (key === (box.dataset.shown || '')) return;
    box.dataset.shown = key;
    if (!d) {
      box.hidden = true;
      box.replaceChildren();
      if (dialogReturn && document.contains(dialogReturn)) dialogReturn.focus();
      dialogReturn = null;
      return;
    }
    if (!dialogReturn && !box.contains(document.activeElement)) dialogReturn = document.activeElement;
    box.replaceChildren(el('h2', { id: 'lab-dialog-title', text: d.title }), el('p', { id: 'lab-dialog-text', text: d.text }),
      ...d.buttons.map(button));
    box.hidden = false;
    // The focus goes to its default button: Enter answers it, Esc the last (dialogKey), as on the canvas.
    const first = box.querySelector('button');
    if (first) first.focus();
  }

  // The speaker's notes while the canvas shows them (S): the slide, its notes, the next slide.
  function notes(n) {
    const region = document.getElementById('lab-notes');
    region.hidden = !n;
    if (!n) return;
    const set = (id, text) => { const e = document.getElementById(id); if (e.textContent !== text) e.textContent = text; };
    set('lab-notes-position', n.position);
    set('lab-notes-text', n.text || 'No notes for this slide.');
    set('lab-notes-next', n.next ? 'Next: ' + n.next : 'The last slide.');
  }

  // A description from the lab (every frame it changed).
  Module.labPage = (text) => {
    const m = JSON.parse(text);
    window.labPageModel = m; // the browser tests read it
    const { title, pictures, messages: said, readouts, dialog: asked, notes: spoken, ...structure } = m;
    const s = JSON.stringify(structure, (k, v) => (k === 'value' || k === 'current' || k === 'score' || k === 'solved') ? undefined : v);
    if (s !== shape) {
      shape = s;
      build(m);
      exercise(m.exercise);
    }
    update(m);
    if (m.exercise) {
      const score = document.getElementById('lab-score');
      const text = m.exercise.solved ? 'Solved. ' + m.exercise.score : m.exercise.score || 'Not scored yet';
      if (score.textContent !== text) score.textContent = text;
    }
    document.getElementById('lab-document').textContent = m.title;
    document.documentElement.dataset.theme = m.theme;
    const theme = document.getElementById('lab-theme');
    if (theme && theme !== document.activeElement) theme.value = m.theme;
    messages(m);
    dialog(asked);
    notes(spoken);
    // The pictures' words once a change has settled (a second without one), not every frame.
    const p = JSON.stringify(m.pictures);
    if (!model || p !== JSON.stringify(model.pictures)) {
      pendingWords = m.pictures;
      clearTimeout(Module.labWordsTimer);
      const wait = describedAt ? 1000 : 0;
      Module.labWordsTimer = setTimeout(() => { words(pendingWords); }, wait);
    }
    model = m;
  };

  // The canvas's widget for the focused control gets the focus ring; none when the focus leaves.
  root.addEventListener('focusin', (e) => {
    const key = e.target.closest('[data-key]');
    focusPath(key && !key.dataset.key.startsWith('command-') ? key.dataset.key : '');
  });
  root.addEventListener('focusout', (e) => { if (!root.contains(e.relatedTarget)) focusPath(''); });
  Module.labAccessKey = (e) => e.type === 'keydown' && ((e.target.getAttribute('role') === 'tab' && tabKey(e)) ||
    (e.target.getAttribute('role') === 'spinbutton' && spinKey(e)) || dialogKey(e)) && (e.preventDefault(), true);
})();
