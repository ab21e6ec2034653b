// The settings panel, built from the server's schema (GET /settings-schema.json): a control per
// setting the protocol carries, grouped as the schema groups them, with its range or choices. Nothing
// here names a setting: a setting added to the schema appears here by itself.
'use strict';

window.SpeculaSettings = (() => {
  let settings = [];  // the schema's entries, in its order

  const controlOf = (setting) => document.getElementById(setting.field);
  // Choices the protocol carries as enum names send those; the others (sample counts) are numbers.
  const isEnum = (setting) => setting.choices.some((choice) => choice.value);

  function controlFor(setting) {
    if (setting.type === 'choice') {
      const select = document.createElement('select');
      for (const choice of setting.choices) {
        const option = new Option(choice.name, choice.value || choice.name);
        option.title = choice.help;
        select.append(option);
      }
      return select;
    }
    const input = document.createElement('input');
    Object.assign(input, { type: 'number', min: setting.min, max: setting.max, step: setting.type === 'integer' ? 1 : 'any' });
    return input;
  }

  // The update one control's value makes, or the reason it cannot be sent.
  function updateFrom(setting) {
    const raw = controlOf(setting).value;
    if (setting.type === 'choice') return { [setting.field]: isEnum(setting) ? raw : Number(raw) };
    const value = Number(raw);
    if (raw === '' || !(value >= setting.min && value <= setting.max) || (setting.type === 'integer' && !Number.isInteger(value)))
      return { problem: `${setting.name} must be ${setting.type === 'integer' ? 'an integer ' : ''}in [${setting.min}, ${setting.max}]` };
    return { [setting.field]: value === 0 ? -1 : value };  // proto3 cannot send 0: -1 stands for it
  }

  // Builds the panel into `container`; `send(update)` gets { field: value } for each change, `refuse(text)` a bad value.
  function build(container, schema, { send, refuse }) {
    settings = schema.settings;
    for (const setting of settings) {
      let section = container.querySelector(`section[data-group="${setting.group}"]`);
      if (!section) {
        section = document.createElement('section');
        section.dataset.group = setting.group;
        const heading = document.createElement('h2');
        heading.textContent = setting.group;
        section.append(heading);
        container.append(section);
      }
      const label = document.createElement('label');
      label.title = setting.help;
      const control = controlFor(setting);
      control.id = setting.field;
      label.append(`${setting.name} `, control);
      section.append(label);
      control.addEventListener('change', () => {
        const { problem, ...update } = updateFrom(setting);
        if (problem) refuse(problem);
        else send(update);
      });
    }
  }

  // Shows the settings a Welcome or Frame carries (every field set).
  function show(values) {
    for (const setting of settings) {
      const value = values[setting.field];
      if (value === undefined || value === null) continue;
      controlOf(setting).value = setting.type === 'choice' ? String(value) : String(value === -1 ? 0 : value);
    }
  }

  // "none (each mirror in its own colour)": a choice setting's current choice and what it does.
  function describe(field) {
    const option = document.getElementById(field)?.selectedOptions?.[0];
    if (!option) return '';
    return option.title ? `${option.textContent} (${option.title})` : option.textContent;
  }

  return { build, show, describe };
})();
