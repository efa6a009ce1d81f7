#!/usr/bin/env python3
# Writes panel.toml and panel_oled.toml (run from the repository root:
# python3 examples/scenes/gen_panel.py).
import math
def f(v): 
    s = f"{v:.3f}".rstrip('0').rstrip('.')
    return s if s not in ('-0',) else '0'
def pt(x,y): return f"[{f(x)}, {f(y)}]"

def panel(W, H, fmt, bg, scale, oled=False, L=None):
    out = []
    k = scale
    out.append(f"""[display]
width = {W}
height = {H}
format = "{fmt}"
background = "{bg}"

[render]
gamma = {'"srgb"' if not oled else '"srgb"'}
band_rows = {16 if not oled else 8}
{'' if oled else 'dither = "ordered"  # the dark radial dial face would band in 5-6-5 steps' + chr(10)}""")
    cx, cy, R = L['dial']
    fg = "#ffffff"
    def col(rgb, grey):
        return grey if oled else rgb
    # Dial face
    face = ('color = "#000000"' if oled else
            f'gradient = {{ kind = "radial", centre = {pt(cx, cy - R/3)}, radius = {f(1.3*R)}, '
            'stops = [{ offset = 0, color = "#34404e" }, { offset = 1, color = "#10161e" }] }')
    out.append(f"""# The dial: a face (a radial gradient, lit from above), a rim, 41 ticks (long every 5th) and
# its numbers.
[[circle]]
centre = {pt(cx, cy)}
radius = {f(R)}
{face}
stroke_color = "{col('#8090a0', '#ffffff')}"
stroke_width = {f(2*k if not oled else 1)}
""")
    # ticks from 135 deg to 405 deg (clockwise on screen from +x), 270 sweep
    n = 40
    for i in range(n+1):
        a = math.radians(135 + 270*i/n)
        long = i % 5 == 0
        r0 = R - (L['tick'][0] if long else L['tick'][1])
        r1 = R - L['tick'][2]
        x0, y0 = cx + r0*math.cos(a), cy + r0*math.sin(a)
        x1, y1 = cx + r1*math.cos(a), cy + r1*math.sin(a)
        w = (2.0 if long else 1.0)*k if not oled else (1.0 if long else 0.75)
        out.append(f"""[[polyline]]
points = [{pt(x0,y0)}, {pt(x1,y1)}]
stroke_color = "{col('#e8eef4' if long else '#a0aab4', '#ffffff')}"
stroke_width = {f(w)}
""")
        if long and not oled:
            rn = R - L['tick'][3]
            out.append(f"""[[text]]
text = "{i // 5 * 10}"
position = {pt(cx + rn*math.cos(a), cy + rn*math.sin(a))}
size = {f(L['place'])}
align = "center"
baseline = "middle"
color = "#c8d2dc"
""")
    # needle at 62% of the range, over the dial
    v = 0.62
    a = math.radians(135 + 270*v)
    tip = (cx + (R-L['needle'][0])*math.cos(a), cy + (R-L['needle'][0])*math.sin(a))
    back = (cx - L['needle'][1]*math.cos(a), cy - L['needle'][1]*math.sin(a))
    nx, ny = -math.sin(a), math.cos(a)
    hw = L['needle'][2]
    p1 = (back[0] + hw*nx, back[1] + hw*ny)
    p2 = (back[0] - hw*nx, back[1] - hw*ny)
    out.append(f"""# The needle, over the dial, and its hub.
[[path]]
d = "M {f(tip[0])} {f(tip[1])} L {f(p1[0])} {f(p1[1])} L {f(p2[0])} {f(p2[1])} Z"
color = "{col('#ff5030', '#ffffff')}"
[[circle]]
centre = {pt(cx, cy)}
radius = {f(L['hub'])}
color = "{col('#d0d8e0', '#ffffff')}"
stroke_color = "{col('#1c2430', '#000000')}"
stroke_width = {f(1.5*k if not oled else 1)}
""")
    # arc gauge on the right
    gx, gy, gr = L['gauge']
    out.append(f"""# An arc gauge: the track, then the value (70 %) over it, round caps.
[[arc]]
centre = {pt(gx, gy)}
radius = {f(gr)}
start = 135
sweep = 270
stroke_color = "{col('#303a48', '#ffffff')}"
stroke_width = {f(8*k if not oled else 1)}
cap = "round"
[[arc]]
centre = {pt(gx, gy)}
radius = {f(gr)}
start = 135
sweep = {f(270*0.7)}
stroke_color = "{col('#30d080', '#ffffff')}"
stroke_width = {f(8*k if not oled else 5)}
cap = "round"
[[text]]
text = "70"
position = {pt(gx, gy)}
size = {f(L['value'])}
align = "center"
baseline = "middle"
color = "{col('#e8eef4', '#ffffff')}"
""")
    # rounded button
    bx, by, bw, bh = L['button']
    button = ('color = "#000000"' if oled else
              f'gradient = {{ kind = "linear", from = {pt(bx, by)}, to = {pt(bx, by + bh)}, '
              'stops = [{ offset = 0, color = "#4a8ae8" }, { offset = 1, color = "#1c4c98" }] }')
    out.append(f"""# A rounded button (a vertical gradient): a shadow at half opacity, the face, a 1.5-px rim.
[[rect]]
position = {pt(bx+2*k, by+3*k)}
size = [{f(bw)}, {f(bh)}]
radius = {f(L['bradius'])}
color = "#000000"
opacity = 0.5
[[rect]]
position = {pt(bx, by)}
size = [{f(bw)}, {f(bh)}]
radius = {f(L['bradius'])}
{button}
stroke_color = "{col('#90b8f0', '#ffffff')}"
stroke_width = {f(1.5*k if not oled else 1)}
stroke_alignment = "inside"
[[text]]
text = "START"
position = {pt(bx + bw/2, by + bh/2)}
size = {f(L['label'])}
align = "center"
baseline = "middle"
color = "#ffffff"
""")
    if oled:
        return "\n".join(out)
    # a small chart line
    pts = []
    (cx0, cy0, step, amp) = L['chart']
    for i in range(9):
        x = cx0 + i*step
        y = cy0 + amp*math.sin(i*0.9) - 0.4*amp*math.cos(i*2.1)
        pts.append(pt(x, y))
    out.append(f"""# A chart line with round joins over a translucent band.
[[rect]]
position = {pt(*L['band'][:2])}
size = [{f(L['band'][2])}, {f(L['band'][3])}]
radius = {f(L['band'][4])}
color = "{col('#ffffff', '#000000')}"
opacity = {0.04 if not oled else 1}
[[polyline]]
points = [{", ".join(pts)}]
stroke_color = "{col('#ffd040', '#ffffff')}"
stroke_width = {f(2*k if not oled else 1)}
join = "round"
cap = "round"
""")
    return "\n".join(out)

TFT = dict(dial=(78,80,62), tick=(12,7,3,22), needle=(8,10,3), hub=6, place=11, value=18, label=14,
           gauge=(180,62,34), button=(138,150,86,34), bradius=10,
           chart=(20,205,13,14), band=(16,186,112,40,4))
OLED = dict(dial=(31,33,29), tick=(6,3,1,0), needle=(5,4,1.5), hub=3, place=0, value=12, label=10,
            gauge=(97,24,18), button=(72,48,52,14), bradius=5,
            chart=(0,-100,0,0), band=(0,-100,0,0,0))
hdr = """# A small instrument panel in painter's order: a dial with ticks and its
# numbers, a needle over it, an arc gauge with its value, a rounded button
# with a translucent shadow and a label, a chart line. Shapes, strokes,
# gradients, text and opacity of scene files; generated once (coordinates
# rounded to 1/1000 px).
"""
open('examples/scenes/panel.toml','w').write(hdr + panel(240,240,"rgb565","#0a0e14",1,L=TFT))
hdr2 = """# The instrument panel of panel.toml on a 128x64 1-bit OLED (Floyd-
# Steinberg in linear light), laid out for its 128x64 pixels, white on
# black: dial, needle, arc gauge and its value, button and its label.
"""
s = panel(128,64,"binary","#000000",0.5, oled=True, L=OLED)
open('examples/scenes/panel_oled.toml','w').write(hdr2 + s)
