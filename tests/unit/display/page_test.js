// The display page's own arithmetic and words, under node (no browser): the part of index.html
// between "PURE BEGIN" and "PURE END", and a few facts of the page itself.
// usage: node page_test.js index.html
"use strict";
const fs = require("fs");
const assert = require("assert");

const page = fs.readFileSync(process.argv[2], "utf8");
const begin = page.indexOf("// PURE BEGIN"), end = page.indexOf("// PURE END");
assert(begin > 0 && end > begin, "the page marks its pure part");
const {angleText, wrapsAround, LENGTH_UNITS, cardTitle, counterText, tickStep, nearestOffsets, stationSd,
       TOOLFACE_TRACE_MAX_RPM, depthText, sectionAlong, differenceText} = new Function(page.slice(begin, end) +
  "\nreturn {angleText, wrapsAround, LENGTH_UNITS, cardTitle, counterText, tickStep, nearestOffsets, stationSd, " +
  "TOOLFACE_TRACE_MAX_RPM, depthText, sectionAlong, differenceText};")();

let checks = 0;
const check = (ok, what) => { assert(ok, what); ++checks; };

// Angles shown in [0, 360) after rounding: one card never says 360.00 while another says 0.00.
check(angleText(359.996) === "0.00", "359.996 shows as 0.00, not 360.00: " + angleText(359.996));
check(angleText(360) === "0.00", "360 shows as 0.00");
check(angleText(-0.001) === "0.00", "-0.001 shows as 0.00: " + angleText(-0.001));
check(angleText(359.994) === "359.99", "359.994 shows as 359.99");
check(angleText(-90) === "270.00", "-90 shows as 270.00");
check(angleText(45.5) === "45.50", "45.5 shows as 45.50");
check(angleText(NaN) === "-" && angleText(null) === "-", "no number: -");

// The nearest offset: per tool, the smallest SF of its newest station (an older station's smaller
// SF no longer counts; no number is the least clear).
{
  const n = nearestOffsets([{tool: "a", i: 3, off: "w1", sf: 1.2}, {tool: "a", i: 4, off: "w2", sf: 2.5},
                            {tool: "a", i: 4, off: "w1", sf: 1.9}, {tool: "b", i: 1, off: "w1", sf: 5},
                            {tool: "b", i: 1, off: "w3", sf: null}]);
  check(n.get("a").off === "w1" && n.get("a").sf === 1.9, "tool a: w1 at its newest station: " + JSON.stringify(n.get("a")));
  check(n.get("b").off === "w3", "tool b: the clearance without a number counts as the least clear");
}

// A station shows the survey's sigma (0.35 deg), not the estimator's (0.001 deg: 45.02 +- 0.00).
check(stationSd(0.35, 0.001) === 0.35, "the survey's total sigma");
check(stationSd(0, 0.02) === 0.02 && stationSd(null, 0.02) === 0.02, "without it, the measurement's");
check(TOOLFACE_TRACE_MAX_RPM > 0 && TOOLFACE_TRACE_MAX_RPM < 30, "the toolface trace stops for a tool turning at 30 rpm");

// The bit depth on a tool's card: valid only, in the chosen unit, with what the string does.
check(depthText({md: 1234.5, flags: 1}, 1, "m") === " · depth 1234.50 m (still)", depthText({md: 1234.5, flags: 1}, 1, "m"));
check(depthText({md: 304.8, flags: 3}, 1 / 0.3048, "ft") === " · depth 1000.00 ft (moving)", "feet, moving");
check(depthText({md: 10, flags: 5}, 1, "m").endsWith("(in slips)"), "in slips");
check(depthText({md: 10, flags: 0}, 1, "m") === "" && depthText(undefined, 1, "m") === "", "no valid depth: nothing");

// The section along the newest station's direction: a station due east is 0 along north, its
// whole distance along east, 10 cos 30 along 60; without a direction, the section it came with.
{
  const s = {n: 0, e: 10, vs: -4};
  check(Math.abs(sectionAlong(s, 0)) < 1e-12 && Math.abs(sectionAlong(s, 90) - 10) < 1e-12, "north 0, east 10");
  check(Math.abs(sectionAlong(s, 60) - 10 * Math.cos(Math.PI / 6)) < 1e-12, "along 60 deg: " + sectionAlong(s, 60));
  check(Math.abs(sectionAlong({n: 3, e: 4}, Math.atan2(4, 3) * 180 / Math.PI) - 5) < 1e-12, "along its own closure: its distance");
  check(sectionAlong(s, undefined) === -4 && sectionAlong(s, null) === -4, "no direction sent: the station's own");
}

// Two plugins of one tool: plumb-display computes each difference (attitude_difference.cpp, checked by
// plumb_display_test's AttitudeDifference.*) and the page draws the one it is given with the
// estimate, as the display's JSON carries it (DisplayJson.AttitudeCarriesItsDifferenceForThePage).
{
  check(!/function differences\(/.test(page) && !page.includes("differences("), "the page computes no difference of its own");
  check(/e\.diff\.textContent = differenceText\(a\.diff\)/.test(page), "a card draws the difference its estimate came with");
  const a = JSON.parse('{"k":"sim/integral","tool":"sim","est":"integral","inc":2.07,"flags":7,' +
                       '"diff":{"ref":"compensated","inc":{"d":0.07,"sd":0.0424},"azi":{"d":-1,"sd":0.424},"tf":null}}');
  check(differenceText(a.diff) === "minus compensated: inclination +0.070 ± 0.042°, azimuth −1.00 ± 0.42°, toolface -",
        differenceText(a.diff));
  const none = JSON.parse('{"diff":{"ref":"compensated","inc":null,"azi":null,"tf":null}}').diff;
  check(differenceText(none) === "minus compensated: inclination -, azimuth -, toolface -", differenceText(none));
  check(differenceText(null) === "" && differenceText(undefined) === "", "the reference's own estimate (diff null): no text");
  check(differenceText({ref: "x", inc: {d: 0.5, sd: 0}, azi: null, tf: null}) === "minus x: inclination +0.500°, azimuth -, toolface -",
        "no sigma given: none shown");
}

// The history breaks its line where the angle wraps, not elsewhere.
check(wrapsAround(359, 1) && wrapsAround(2, 358), "359 -> 1 and 2 -> 358 wrap");
check(!wrapsAround(10, 20) && !wrapsAround(170, 190), "10 -> 20 and 170 -> 190 do not");

// Metres or feet; dogleg per 30 m or per 100 ft.
check(Math.abs(100 * LENGTH_UNITS.ft.perLength - 328.084) < 1e-3, "100 m is 328.084 ft");
check(LENGTH_UNITS.m.perLength === 1 && LENGTH_UNITS.m.perDls === 1, "metres are the survey's own unit");
check(Math.abs(3 * LENGTH_UNITS.ft.perDls - 3.048) < 1e-9, "3 deg/30 m is 3.048 deg/100 ft");

// The plan and section's ticks: 1, 2 or 5 times a power of ten, about five to a span.
check(tickStep(10) === 2 && tickStep(3) === 1 && tickStep(240) === 50, "tick steps " + [tickStep(10), tickStep(3), tickStep(240)]);
check(Math.abs(tickStep(0.04) - 0.01) < 1e-15, "tick step of 0.04 m: " + tickStep(0.04));

// Words for people.
check(cardTitle("sim", "compensated") === "tool sim, compensated estimator", "card name: " + cardTitle("sim", "compensated"));
check(cardTitle("", "static") === "unnamed tool, static estimator", "card without tool id");
check(counterText("lost_samples", 3) === "samples lost 3", counterText("lost_samples", 3));
check(counterText("compensated.gaps", 1) === "compensated: gaps 1", counterText("compensated.gaps", 1));
check(counterText("some_new_counter", 2) === "some new counter 2", "an unlisted counter loses its underscores");

// The page: the reason wraps whole, the unit choice is kept, no developers' dot in names.
check(/\.why \{[^}]*white-space:normal/.test(page), "the invalid reason wraps");
check(page.includes('localStorage.setItem("plumb.units"'), "the unit choice is kept in localStorage");
check(!page.includes('" · "'), "no 'tool · estimator' names");
console.log(`page_test: ${checks} checks passed`);
