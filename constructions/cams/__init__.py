"""The cam chapter: follower motion drawn by construction (000-part2 §2.16, §3.20)."""
