// Structural rules every LD body the editor produces must satisfy. The backend checks meaning
// (types, unknown names, jump targets); these are the shape rules an edit can break, so every
// editing operation runs them on its result and refuses an edit that would leave a broken rung.
import { boxInputs, childSeries, elementsOf, networksOf, type LdBody, type LdElement, type Series } from "./model";

export interface LdProblem {
  network: string;
  element?: string;
  message: string;
}

/** Network labels are IEC identifiers or unsigned decimal integers (GR-03). */
const LABEL = /^(?:[A-Za-z_][A-Za-z0-9_]*|[0-9]+)$/;

/** Coils, jumps and returns end a rung; a parallel holding one is an output too. */
export function isOutput(element: LdElement): boolean {
  if (element.type === "coil" || element.type === "jump" || element.type === "return") return true;
  return element.type === "parallel" && element.branches.some((branch) => branch.some(isOutput));
}

/**
 * The problems of a body, empty when valid:
 * - network ids and element ids are non-empty and unique (ids are the probe ids of power flow);
 * - labels are unique (ignoring case) identifiers or unsigned integers;
 * - a parallel has two or more branches, none empty;
 * - coils last: after an output in a series only outputs follow; a jump or return ends its series;
 * - a box input series is non-empty and holds no outputs (it only feeds a pin); a box names its call.
 */
export function ldProblems(body: LdBody): LdProblem[] {
  const problems: LdProblem[] = [];
  const networkIds = new Set<string>();
  const elementIds = new Set<string>();
  const labels = new Set<string>();

  const checkSeries = (network: string, series: Series, feedsPin: boolean) => {
    let afterOutput = false;
    series.forEach((element, index) => {
      const report = (message: string) => problems.push({ network, element: element.id, message });
      if (!element.id) report("element without an id");
      else if (elementIds.has(element.id)) report(`duplicate element id ${element.id}`);
      elementIds.add(element.id);
      const output = isOutput(element);
      if (feedsPin && output)
        report(`a box input cannot hold a ${element.type === "parallel" ? "coil" : element.type}`);
      if (afterOutput && !output) report(`${element.type} after a coil: coils come last`);
      if ((element.type === "jump" || element.type === "return") && index !== series.length - 1) {
        report(`${element.type} must be the last element of its branch`);
      }
      afterOutput ||= output;
      if (element.type === "parallel") {
        if (element.branches.length < 2) report("a parallel needs at least two branches");
        if (element.branches.some((b) => b.length === 0)) report("a parallel branch is empty");
      }
      if (element.type === "box") {
        if (!element.call) report("a box without a function or function block name");
        for (const [pin, value] of Object.entries(boxInputs(element))) {
          if (Array.isArray(value) && value.length === 0) report(`input ${pin} is fed by an empty series`);
        }
      }
      for (const child of childSeries(element))
        checkSeries(network, child.series, feedsPin || child.ref.kind === "pin");
    });
  };

  for (const network of networksOf(body)) {
    if (!network.id) problems.push({ network: "", message: "network without an id" });
    else if (networkIds.has(network.id))
      problems.push({ network: network.id, message: `duplicate network id ${network.id}` });
    networkIds.add(network.id);
    if (network.label != null) {
      if (!LABEL.test(network.label)) {
        problems.push({
          network: network.id,
          message: `label ${JSON.stringify(network.label)} is not an identifier or number`,
        });
      } else if (labels.has(network.label.toUpperCase())) {
        problems.push({ network: network.id, message: `label ${network.label} is used twice` });
      }
      labels.add(network.label.toUpperCase());
    }
    checkSeries(network.id, elementsOf(network), false);
  }
  return problems;
}

export const isValidLabel = (label: string): boolean => LABEL.test(label);
