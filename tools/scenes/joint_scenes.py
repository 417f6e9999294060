#!/usr/bin/env python3
"""joint_scenes.py — write the joint scenes of scenes/ whose coordinates are computed
(a row, a chain, a ring): newtons_cradle, chain40, bridge and soft_blob_bowl.

    python3 tools/scenes/joint_scenes.py        (from the repository root)

The scene files are the source the tests, the corpus and the front ends read; this
script only saves typing their numbers. Numbers are written with at most 6 decimals,
which the reader rounds to Q16.16 exactly (pg_fix_parse)."""
import math
import os

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..')
ROOM = 'max_bodies 256\nmax_shapes 512\nmax_contacts 2048\nmax_joints 256\n'


def num(v):
    s = ('%.6f' % v).rstrip('0').rstrip('.')
    return '0' if s in ('-0', '') else s


def write(name, text):
    with open(os.path.join(ROOT, 'scenes', name + '.scene'), 'w') as f:
        f.write(text)


def cradle():
    # five balls of radius 0.5 in a row at y = 4, 5 cm apart, each on a 4 m rod from a bar
    # at y = 8; ball 1 (body 1) is pulled out to 45 degrees on its rod. The gap makes each
    # collision one pair at a time: balls in contact together share the strike in the
    # solver and leave as a block (docs/soft-bodies.md, "Newton's cradle").
    r, rod, bar_y, n, gap = 0.5, 4.0, 8.0, 5, 0.05
    xs = [(i - (n - 1) / 2.0) * (2 * r + gap) for i in range(n)]
    t = ['pogon-scene 1',
         "# newtons_cradle: five balls of radius 0.5 m in a row, 5 cm apart, each hung from a static",
         "# bar by a 4 m rod (a rigid distance joint), restitution 1 and no friction. The first",
         "# ball is pulled out to 45 degrees on its rod and released: it strikes the row at",
         "# about 4.7 m/s and the last ball leaves at that speed (test_newtons_cradle). Balls",
         "# that touch would share the strike and leave together. Written by",
         "# tools/scenes/joint_scenes.py.",
         '', ROOM.rstrip(), '',
         '# body 0: the bar (no shapes), with the rods\' upper ends at y = 8',
         'body static', '  position 0 %s' % num(bar_y), 'end']
    for i, x in enumerate(xs):
        if i == 0:
            a = math.radians(45)
            px, py = x - rod * math.sin(a), bar_y - rod * math.cos(a)
        else:
            px, py = x, bar_y - rod
        t.append('ball %s position %s %s restitution 1 friction 0 user_data %d' % (num(r), num(px), num(py), i + 1))
    for i, x in enumerate(xs):
        t.append('joint distance 0 %d local_anchor_a %s 0 length %s' % (i + 1, num(x), num(rod)))
    write('newtons_cradle', '\n'.join(t) + '\n')


def chain():
    n, link = 40, 0.5
    t = ['pogon-scene 1',
         '# chain40: 40 capsule links of 0.5 m (0.3 m between cap centres, radius 0.1), pinned',
         '# end to end by revolute joints, the first to a static pin at (0, 20); the chain starts',
         '# straight out to the right and swings down. Written by tools/scenes/joint_scenes.py.',
         '', ROOM.rstrip(), '',
         'wall 60 1 position 0 -0.5                  # body 0: the ground',
         'body static                                # body 1: the pin (no shapes)',
         '  position 0 20', 'end']
    for i in range(n):
        t.append('capsule 0.3 0.1 position %s 20' % num(link / 2 + link * i))
    t.append('joint revolute 1 2 local_anchor_b %s 0' % num(-link / 2))
    for i in range(1, n):
        t.append('joint revolute %d %d local_anchor_a %s 0 local_anchor_b %s 0' % (i + 1, i + 2, num(link / 2), num(-link / 2)))
    write('chain40', '\n'.join(t) + '\n')


def bridge():
    n, w = 20, 1.0
    span = n * w
    t = ['pogon-scene 1',
         '# bridge: a suspension bridge of 20 planks (1 m x 0.25 m) joined edge to edge by',
         '# revolute joints and hung from two static anchors 20 m apart at y = 6; it sags under',
         '# its own weight and under three boxes dropped on it. Written by',
         '# tools/scenes/joint_scenes.py.',
         '', ROOM.rstrip(), '',
         'wall 40 1 position 0 -0.5                  # body 0: the ground',
         'wall 1 6 position %s 3                    # body 1: the left tower' % num(-span / 2 - 0.5),
         'wall 1 6 position %s 3                     # body 2: the right tower' % num(span / 2 + 0.5)]
    for i in range(n):
        t.append('box %s 0.25 position %s 6 friction 0.8' % (num(w), num(-span / 2 + w / 2 + w * i)))
    t += ['box 1 1 position -4 8 density 2', 'box 1 1 position 0 9 density 2', 'ball 0.5 position 4 8 density 2']
    # towers' tops at y = 6: the anchors are their top inner corners
    t.append('joint revolute 1 3 local_anchor_a 0.5 3 local_anchor_b %s 0' % num(-w / 2))
    for i in range(1, n):
        t.append('joint revolute %d %d local_anchor_a %s 0 local_anchor_b %s 0' % (i + 2, i + 3, num(w / 2), num(-w / 2)))
    t.append('joint revolute 2 %d local_anchor_a -0.5 3 local_anchor_b %s 0' % (n + 2, num(w / 2)))
    write('bridge', '\n'.join(t) + '\n')


def bowl_outline():
    """The U, counter-clockwise: the outside (the inside offset by 0.4 m), then the inside."""
    t, h, w = 0.4, 3.0, 4.0
    ox = w + t * (math.sqrt(2) - 1)  # the outer side x - y = w + t sqrt(2), at y = -t
    return [(-ox, -t), (ox, -t), (ox + h + t, h), (w + h, h), (w, 0), (-w, 0), (-w - h, h), (-ox - h - t, h)]


def blob():
    n, ring, cy = 12, 1.2, 9.0
    side = 2 * ring * math.sin(math.pi / n)
    t = ['pogon-scene 1',
         '# soft_blob_bowl: a soft blob (a ball of radius 0.3 m ringed by 12 balls of radius 0.2 m,',
         '# each ring ball joined to the centre and to its two neighbours by distance springs of',
         '# 4 Hz and damping ratio 0.5) falls into a bowl: one static concave body, a U of 8',
         '# vertices (a flat bottom 8 m wide, sides at 45 degrees 3 m high, walls 0.4 m thick).',
         '# Written by tools/scenes/joint_scenes.py.',
         '', ROOM.rstrip(), '',
         '# body 0: the bowl; its inside floor is y = 0 from x = -4 to 4',
         'concave %s type static friction 0.8' % ' '.join(num(c) for p in bowl_outline() for c in p),
         'ball 0.3 position 0 %s                    # body 1: the centre' % num(cy)]
    for i in range(n):
        a = 2 * math.pi * i / n
        t.append('ball 0.2 position %s %s friction 0.8' % (num(ring * math.cos(a)), num(cy + ring * math.sin(a))))
    spring = 'enable_spring 1 hertz 4 damping_ratio 0.5'
    for i in range(n):
        t.append('joint distance 1 %d length %s %s' % (i + 2, num(ring), spring))
    for i in range(n):
        t.append('joint distance %d %d length %s %s' % (i + 2, (i + 1) % n + 2, num(side), spring))
    write('soft_blob_bowl', '\n'.join(t) + '\n')


if __name__ == '__main__':
    cradle()
    chain()
    bridge()
    blob()
