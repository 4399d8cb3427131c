// Where a breakpoint is, in the user's words, from the POU's body: the network's number, label and comment, the
// element by its operand ("coil Motor"), the ST line's text. Shared by the Breakpoints panel and the messages
// of breakpoints dropped because what they were on is gone.
import type { LdBody, Pou } from "../generated/api";
import { locate } from "../ld/model";
import { partAt, elementText as sfcElementText, type SfcBody } from "../sfc/model";
import { partName, type Breakpoint } from "../debug/breakpoints";

/** The networks of a diagram body (LD or FBD), enough to number and name them. */
type Networks = readonly { id: string; label?: string | null; comment?: string | null }[];

/** What an LD element is, in a few words ("coil Motor", "TON RunTimer"); null for unknown ids. */
function ldElementText(body: LdBody, id: string): string | null {
  const e = locate(body, id)?.element;
  if (!e) return null;
  switch (e.type) {
    case "contact":
    case "coil":
      return `${e.type} ${e.var}`;
    case "compare":
      return `${e.left} ${e.op} ${e.right}`;
    case "box":
      return [e.call, e.instance].filter(Boolean).join(" ");
    case "jump":
      return `jump to ${e.target}`;
    default:
      return e.type ?? "contact";
  }
}

/** The body a breakpoint is in and its language: the POU's, or in an SFC POU the action or named transition
 * `bp.body` names ("actions/Fill"). */
export function breakpointBody(
  bp: Breakpoint,
  pou: Pou | undefined,
): { body: Pou["body"] | undefined; language: string | undefined } {
  if (!bp.body || pou?.language !== "sfc") return { body: pou?.body, language: pou?.language };
  const part = partAt(pou.body as SfcBody, bp.body);
  return { body: part?.body as Pou["body"] | undefined, language: part?.language };
}

/** Where a breakpoint is, in words: "network 2 seal_in: comment", "element motor (coil Motor)", "line 3: Count := Count + 1;";
 * in an SFC action or named transition, that part first ("action Fill, line 2: m := m + n;"). */
export function describePlace(
  bp: Breakpoint,
  pou: Pou | undefined,
  body: Pou["body"] | undefined,
  language: string | undefined = pou?.language,
): string {
  const place = describeIn(bp, body, language);
  return bp.body ? `${partName(bp.body)}, ${place}` : place;
}

function describeIn(bp: Breakpoint, body: Pou["body"] | undefined, language: string | undefined): string {
  const networks: Networks = body && typeof body === "object" && "networks" in body ? (body.networks ?? []) : [];
  if ("line" in bp) {
    const text = typeof body === "string" ? body.split("\n")[bp.line - 1]?.trim() : undefined;
    return text ? `line ${bp.line}: ${text}` : `line ${bp.line}`;
  }
  if ("network" in bp) {
    const index = networks.findIndex((n) => n.id === bp.network);
    if (index < 0) return `network ${bp.network} (not in the ${bp.body ? partName(bp.body).split(" ")[0] : "POU"})`;
    const n = networks[index]!;
    const comment = n.comment?.split("\n")[0];
    return [`network ${index + 1}`, n.label ? `${n.label}:` : null, comment].filter(Boolean).join(" ");
  }
  const what =
    body && typeof body === "object"
      ? language === "ld"
        ? ldElementText(body as LdBody, bp.element)
        : language === "sfc"
          ? sfcElementText(body as SfcBody, bp.element)
          : null
      : null;
  return what ? `element ${bp.element} (${what})` : `element ${bp.element}`;
}
