"""Persian words of a graded drawing's overlay, the student's feedback page and the
class's summary plot (exercises/grading/overlay.py, feedback.py, summary.py).

Keys are the English words as the grading code says them
(:func:`~tarsim.constructions.narration.words`); the verdicts themselves are in fa.py.
"""

from __future__ import annotations

WORDS: dict[str, str] = {
    # the overlay's legend
    "your drawing": "ترسیم شما", "expected": "مورد انتظار", "graded wrong": "نادرست",
    "follows from an earlier error": "پیامد خطای پیشین",
    # the feedback page
    "Feedback: {who}": "بازخورد: {who}",
    "{exercise}, position {position}: {drawing}": "{exercise}، وضعیت {position}: {drawing}",
    "score {score} % ({credited} of {total} items credited)":
        "نمره {score}٪ ({credited} مورد از {total} پذیرفته)",
    "item": "مورد", "verdict": "نتیجه", "tolerance": "رواداری", "advice": "راهنمایی",
    "notes": "یادداشت\u200cها",
    # the class's summary
    "{exercise}: {graded} drawings graded, mean score {mean} %":
        "{exercise}: {graded} ترسیم ارزیابی شد، میانگین نمره {mean}٪",
    "{unread} files could not be graded (see grades.csv)":
        "{unread} فایل ارزیابی نشد (grades.csv را ببینید)",
    "Scores": "نمره\u200cها", "score (%)": "نمره (٪)", "drawings": "تعداد ترسیم\u200cها",
    "Each item's error rate (share of drawings where it was not correct)":
        "نرخ خطای هر مورد (سهم ترسیم\u200cهایی که در آن\u200cها درست نبود)",
    "no drawing could be graded": "هیچ ترسیمی ارزیابی نشد",
    "{share} % ({wrong} of {graded})": "{share}٪ ({wrong} از {graded})", "{pct} %": "{pct}٪",
}
"""Small words and headings of grading as Persian says them."""
