// The slicing parameters, with the CLI's names, defaults, units and ranges (strata slice --help).

const FIELDS = [
  { key: 'layer', flag: '--layer', label: 'layer thickness dz', unit: 'mm', value: 0.1, min: 0, exclusive: true, step: 'any' },
  { key: 'cell', flag: '--cell', label: 'cell size in x and y', unit: 'mm', value: 0.1, min: 0, exclusive: true, step: 'any', group: 'cell' },
  { key: 'dx', flag: '--dx', label: 'cell size in x', unit: 'mm', value: 0.1, min: 0, exclusive: true, step: 'any', group: 'dxdy' },
  { key: 'dy', flag: '--dy', label: 'cell size in y', unit: 'mm', value: 0.1, min: 0, exclusive: true, step: 'any', group: 'dxdy' },
  { key: 'shell', flag: '--shell', label: 'boundary shell thickness t', unit: 'mm', value: 0.5, min: 0, step: 'any' },
  { key: 'shell_mode', flag: '--shell-mode', label: 'shell rule', choices: [['distance', 'distance'], ['layers', 'layers (published)']], hint: 'distance: cells whose centre is closer than t to the surface; layers: int(t/d) rings of cells' },
  { key: 'fill_rule', flag: '--fill-rule', label: 'fill rule', choices: [['nonzero', 'nonzero'], ['evenodd', 'evenodd (published)'], ['winding', 'winding']], hint: 'nonzero: union of all shells; evenodd: parity (the published rule); winding: generalized winding number (open meshes)' },
  { key: 'scan_offset', flag: '--scan-offset', label: 'scanline shift in +y', unit: 'mm', value: 0, step: 'any' },
  { key: 'kernel', flag: '--kernel', label: 'arithmetic', choices: [['fast', 'fast'], ['exact', 'exact (CGAL)']], hint: 'fast: double with exact predicates; exact: CGAL' },
  { key: 'origin', flag: '--origin', label: 'grid origin X,Y,Z', unit: 'mm', text: true, placeholder: "model's minimum corner" },
  { key: 'repair', flag: '--repair', label: 'repair the mesh first', check: true },
  { key: 'fill_holes', flag: '--fill-holes', label: 'with repair: fill holes', check: true },
];

export class OptionsForm {
  constructor(form) {
    this.form = form;
    this.inputs = new Map();
    const mode = document.createElement('div');
    mode.className = 'row mode';
    mode.innerHTML =
      '<span class="flag">cells</span><label><input type="radio" name="cell-mode" value="cell" checked data-testid="mode-cell"> square (--cell)</label>' +
      '<label><input type="radio" name="cell-mode" value="dxdy" data-testid="mode-dxdy"> dx, dy</label>';
    for (const field of FIELDS) {
      if (field.key === 'cell') form.append(mode);
      const row = document.createElement('label');
      row.className = `row${field.group ? ` group-${field.group}` : ''}${field.check ? ' check' : ''}`;
      row.title = `${field.flag}${field.unit ? ` (${field.unit})` : ''}${field.hint ? `: ${field.hint}` : ''}`;
      let input;
      if (field.choices) {
        input = document.createElement('select');
        for (const [value, text] of field.choices) input.append(new Option(text, value));
      } else {
        input = document.createElement('input');
        if (field.check) input.type = 'checkbox';
        else if (field.text) {
          input.type = 'text';
          input.placeholder = field.placeholder;
        } else {
          input.type = 'number';
          input.step = field.step;
          if (field.min != null) input.min = field.min;
          input.value = field.value;
        }
      }
      input.name = field.key;
      input.dataset.testid = `option-${field.key}`;
      this.inputs.set(field.key, input);
      const flag = document.createElement('span');
      flag.className = 'flag';
      flag.textContent = field.flag;
      const text = document.createElement('span');
      text.className = 'what';
      text.textContent = field.label;
      const unit = document.createElement('span');
      unit.className = 'unit';
      unit.textContent = field.unit ?? '';
      if (field.check) row.append(input, flag, text);
      else row.append(flag, text, input, unit);
      form.append(row);
    }
    form.addEventListener('change', () => this.update());
    this.update();
  }

  get mode() {
    return this.form.querySelector('input[name="cell-mode"]:checked').value;
  }

  update() {
    const dxdy = this.mode === 'dxdy';
    for (const row of this.form.querySelectorAll('.group-cell')) row.hidden = dxdy;
    for (const row of this.form.querySelectorAll('.group-dxdy')) row.hidden = !dxdy;
    this.inputs.get('fill_holes').disabled = !this.inputs.get('repair').checked;
  }

  /** The options as the server takes them, or throws an Error naming the bad field. */
  values() {
    const out = {};
    const number = (key) => {
      const field = FIELDS.find((f) => f.key === key);
      const raw = this.inputs.get(key).value.trim();
      const v = Number(raw);
      if (raw === '' || !Number.isFinite(v)) throw new Error(`${field.flag}: a number is needed`);
      if (field.exclusive && !(v > field.min)) throw new Error(`${field.flag} must be greater than ${field.min} ${field.unit}`);
      if (!field.exclusive && field.min != null && v < field.min) throw new Error(`${field.flag} must be at least ${field.min} ${field.unit}`);
      return v;
    };
    out.layer = number('layer');
    if (this.mode === 'dxdy') {
      out.dx = number('dx');
      out.dy = number('dy');
    } else {
      out.cell = number('cell');
    }
    out.shell = number('shell');
    out.shell_mode = this.inputs.get('shell_mode').value;
    out.fill_rule = this.inputs.get('fill_rule').value;
    out.scan_offset = number('scan_offset');
    out.kernel = this.inputs.get('kernel').value;
    const origin = this.inputs.get('origin').value.trim();
    if (origin !== '') {
      const parts = origin.split(',').map((s) => Number(s.trim()));
      if (parts.length !== 3 || !parts.every(Number.isFinite)) throw new Error('--origin takes three numbers X,Y,Z');
      out.origin = parts;
    }
    out.repair = this.inputs.get('repair').checked;
    out.fill_holes = out.repair && this.inputs.get('fill_holes').checked;
    return out;
  }

  /** Puts a job's options back in the form. */
  set(options) {
    if (!options) return;
    const dxdy = options.dx != null;
    this.form.querySelector(`input[name="cell-mode"][value="${dxdy ? 'dxdy' : 'cell'}"]`).checked = true;
    for (const [key, input] of this.inputs) {
      const v = options[key];
      if (v == null) continue;
      if (input.type === 'checkbox') input.checked = !!v;
      else if (key === 'origin') input.value = Array.isArray(v) ? v.join(',') : '';
      else input.value = v;
    }
    if (options.origin == null) this.inputs.get('origin').value = '';
    this.update();
  }
}

/** A short text of a job's options, for the job list. */
export function optionsSummary(o) {
  if (!o) return '';
  const cell = o.dx != null ? `${o.dx}×${o.dy}` : o.cell ?? 0.1;
  const parts = [`cell ${cell}`, `layer ${o.layer ?? 0.1}`, `shell ${o.shell ?? 0.5}`];
  if (o.shell_mode === 'layers') parts.push('layers');
  if (o.fill_rule && o.fill_rule !== 'nonzero') parts.push(o.fill_rule);
  if (o.kernel === 'exact') parts.push('exact');
  if (o.scan_offset) parts.push(`offset ${o.scan_offset}`);
  if (o.repair) parts.push('repair');
  return parts.join(' · ');
}
