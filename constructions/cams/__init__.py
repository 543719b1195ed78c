"""Disk cams: follower motion laws and programs (:mod:`.laws`), the exact profile of a translating follower
(:mod:`.profile`), the graphical construction as the notes draw it (:mod:`.construction`), the s-v-a-j
charts (:mod:`.charts`) and the independent closed-form check (:mod:`.check`)."""
