// A control for one live tunable that the server announces in its `hello` (hello.parameters), each
// {name, symbol, label, unit, kind: real|integer|boolean|choice, min, max (null: no bound),
// choices, default, help}: a real in a range no wider than 1 a slider with its value beside it,
// other numbers a number input, a boolean a checkbox, a choice a select. The control's id is the
// parameter's name (the `params` message's key), its title the parameter's help.

const finite = (x) => typeof x === 'number' && Number.isFinite(x);

function element(tag, attributes = {}) {
  const el = document.createElement(tag);
  for (const [k, v] of Object.entries(attributes)) el.setAttribute(k, String(v));
  return el;
}

/** "symbol label (unit)", each part when the parameter has it. */
function captionOf(p) {
  return [p.symbol, p.label || p.name, p.unit ? `(${p.unit})` : ''].filter(Boolean).join(' ');
}

function numberInput(p) {
  const slider = p.kind === 'real' && finite(p.min) && finite(p.max) && p.max - p.min <= 1;
  const step = slider ? (p.max - p.min) / 100 : (p.kind === 'integer' ? 1 : 'any');
  const input = element('input', { type: slider ? 'range' : 'number', step });
  if (finite(p.min)) input.setAttribute('min', String(p.min));
  if (finite(p.max)) input.setAttribute('max', String(p.max));
  return input;
}

function choiceInput(p) {
  const select = element('select');
  for (const c of p.choices ?? []) {
    const option = element('option', { value: c });
    option.textContent = c;
    select.append(option);
  }
  return select;
}

/** Why the text of a number input is no value of p (a short message), or null. */
function numberProblem(p, text) {
  const name = p.symbol || p.label || p.name;
  const x = Number(text);
  if (text.trim() === '' || !Number.isFinite(x)) return `${name}: a number, please`;
  if (p.kind === 'integer' && !Number.isInteger(x)) return `${name}: a whole number, please`;
  const low = finite(p.min) && x < p.min, high = finite(p.max) && x > p.max;
  if (!low && !high) return null;
  if (finite(p.min) && finite(p.max)) return `${name} must be from ${p.min} to ${p.max}`;
  return low ? `${name} must be at least ${p.min}` : `${name} must be at most ${p.max}`;
}

/** The control of parameter p: `label` (the element for the panel, with the input in it), `input`,
 * `read()` ({value} or {problem: a short message}), `show(value)`. */
export function parameterControl(p) {
  const kind = p.kind;
  const input = kind === 'boolean' ? element('input', { type: 'checkbox' })
    : kind === 'choice' ? choiceInput(p) : numberInput(p);
  input.id = p.name;
  const label = element('label');
  if (p.help) label.title = input.title = p.help;
  const caption = captionOf(p);
  let output = null;
  if (input.type === 'range') {
    output = element('output', { id: `${p.name}-value`, for: p.name });
    input.addEventListener('input', () => { output.textContent = Number(input.value).toFixed(2); });
  }
  if (kind === 'boolean') label.append(input, ` ${caption}`);
  else label.append(`${caption} `, input, ...(output ? [' ', output] : []));
  const control = {
    parameter: p, label, input,
    read() {
      if (kind === 'boolean') return { value: input.checked };
      if (kind === 'choice') return { value: input.value };
      const problem = numberProblem(p, input.value);
      return problem ? { problem } : { value: Number(input.value) };
    },
    show(value) {
      if (kind === 'boolean') input.checked = Boolean(value);
      else input.value = String(value);
      if (output) output.textContent = Number(input.value).toFixed(2);
    },
  };
  if (p.default !== undefined && p.default !== null) control.show(p.default);
  return control;
}
