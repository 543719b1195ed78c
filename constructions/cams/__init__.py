"""Disk cams: follower motion laws and programs (:mod:`.laws`), the follower (:mod:`.follower`) and the turns
between the fixed and the cam frame (:mod:`.frames`), the exact profile as an analytic envelope
(:mod:`.envelope`) and its analysis (:mod:`.profile`, searching along the cam angle with :mod:`.search` and
trimming folds with :mod:`.trimming`), the profile alone for export (:mod:`.sampling`), the graphical
construction as the notes draw it (:mod:`.construction`), the s-v-a-j charts (:mod:`.charts`) and the
independent closed-form check (:mod:`.check`)."""
