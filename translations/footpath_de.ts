<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>footpath</name>
    <message>
        <source>Figure</source>
        <translation>Kennzahl</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Path length (between stances)</source>
        <translation>Weglänge (zwischen Standphasen)</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>Steps (strides of this foot)</source>
        <translation>Schritte (Doppelschritte dieses Fußes)</translation>
    </message>
    <message>
        <source>Cadence, both feet</source>
        <translation>Schrittfrequenz, beide Füße</translation>
    </message>
    <message>
        <source>%1 steps/min</source>
        <translation>%1 Schritte/min</translation>
    </message>
    <message>
        <source>Mean stride length</source>
        <translation>Mittlere Doppelschrittlänge</translation>
    </message>
    <message>
        <source>%1 m (sd %2 m)</source>
        <translation>%1 m (SD %2 m)</translation>
    </message>
    <message>
        <source>Mean stride duration</source>
        <translation>Mittlere Doppelschrittdauer</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Mean stance duration</source>
        <translation>Mittlere Standphasendauer</translation>
    </message>
    <message>
        <source>End-to-start distance</source>
        <translation>Abstand Ende–Start</translation>
    </message>
    <message>
        <source>%1 m = %2 % of the path</source>
        <translation>%1 m = %2 % des Wegs</translation>
    </message>
    <message>
        <source>ARMSE 2D / 3D against the reference</source>
        <translation>ARMSE 2D / 3D gegenüber der Referenz</translation>
    </message>
    <message>
        <source>%1 m / %2 m</source>
        <translation>%1 m / %2 m</translation>
    </message>
    <message>
        <source>Loop closure (DBSE)</source>
        <translation>Schleifenschluss (DBSE)</translation>
    </message>
    <message>
        <source>%1 m = %2 %</source>
        <translation>%1 m = %2 %</translation>
    </message>
    <message>
        <source>Distance error</source>
        <translation>Streckenfehler</translation>
    </message>
    <message>
        <source>%1 m = %2 % of %3 m</source>
        <translation>%1 m = %2 % von %3 m</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>Standard</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>Bedeutung</translation>
    </message>
    <message>
        <source>on</source>
        <translation>ein</translation>
    </message>
    <message>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <source>Stance from (s)</source>
        <translation>Standphase von (s)</translation>
    </message>
    <message>
        <source>to (s)</source>
        <translation>bis (s)</translation>
    </message>
    <message>
        <source>Stride (m)</source>
        <translation>Doppelschritt (m)</translation>
    </message>
    <message>
        <source>Stride (s)</source>
        <translation>Doppelschritt (s)</translation>
    </message>
    <message>
        <source>x (m)</source>
        <translation>x (m)</translation>
    </message>
    <message>
        <source>y (m)</source>
        <translation>y (m)</translation>
    </message>
    <message>
        <source>z (m)</source>
        <translation>z (m)</translation>
    </message>
    <message>
        <source>Recording</source>
        <translation>Aufzeichnung</translation>
    </message>
    <message>
        <source>Format</source>
        <translation>Format</translation>
    </message>
    <message>
        <source>Sensor / device</source>
        <translation>Sensor / Gerät</translation>
    </message>
    <message>
        <source>not stated in the file</source>
        <translation>in der Datei nicht angegeben</translation>
    </message>
    <message>
        <source>Duration</source>
        <translation>Dauer</translation>
    </message>
    <message>
        <source>%1 s, %2 samples</source>
        <translation>%1 s, %2 Abtastwerte</translation>
    </message>
    <message>
        <source>Sample rate</source>
        <translation>Abtastrate</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Method set</source>
        <translation>Verfahren</translation>
    </message>
    <message>
        <source>Report made</source>
        <translation>Bericht erstellt</translation>
    </message>
    <message>
        <source>Software</source>
        <translation>Software</translation>
    </message>
    <message>
        <source>Footpath %1</source>
        <translation>Footpath %1</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>height z (m)</source>
        <translation>Höhe z (m)</translation>
    </message>
    <message>
        <source>Figure 6. Stride length per step.</source>
        <translation>Abbildung 6. Doppelschrittlänge je Schritt.</translation>
    </message>
    <message>
        <source>step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <source>stride length (m)</source>
        <translation>Doppelschrittlänge (m)</translation>
    </message>
    <message>
        <source>Figure 7. Stance duration per step.</source>
        <translation>Abbildung 7. Standphasendauer je Schritt.</translation>
    </message>
    <message>
        <source>stance duration (s)</source>
        <translation>Standphasendauer (s)</translation>
    </message>
    <message>
        <source>Figure 8. Histograms of stride length (left) and stance duration (right).</source>
        <translation>Abbildung 8. Histogramme der Doppelschrittlänge (links) und der Standphasendauer (rechts).</translation>
    </message>
    <message>
        <source>strides</source>
        <translation>Doppelschritte</translation>
    </message>
    <message>
        <source>stances</source>
        <translation>Standphasen</translation>
    </message>
    <message>
        <source>Figure 1. The foot path seen from above (stance positions as dots; reference dashed when present).</source>
        <translation>Abbildung 1. Der Weg des Fußes von oben (Standphasen als Punkte; Referenz gestrichelt, falls vorhanden).</translation>
    </message>
    <message>
        <source>Figure 2. Height of the foot over time.</source>
        <translation>Abbildung 2. Höhe des Fußes über der Zeit.</translation>
    </message>
    <message>
        <source>Figure 4. Signals, stance shaded.</source>
        <translation>Abbildung 4. Signale, Standphasen schattiert.</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>nothing to report: no estimate yet</source>
        <translation>nichts zu berichten: noch keine Schätzung</translation>
    </message>
    <message>
        <source>Footpath report: %1</source>
        <translation>Footpath-Bericht: %1</translation>
    </message>
    <message>
        <source>%1: cannot write the PDF</source>
        <translation>%1: PDF kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>Footpath report</source>
        <translation>Footpath-Bericht</translation>
    </message>
    <message>
        <source>Summary</source>
        <translation>Zusammenfassung</translation>
    </message>
    <message>
        <source>Figures</source>
        <translation>Abbildungen</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>Schritte</translation>
    </message>
    <message>
        <source>Figure 5. Stance detector C1/C2/C3 from %1 s to %2 s: conditions C1, C2, C3, their combination C, the median-filtered stance, the std of |a| on a logarithmic axis, and the inputs with their thresholds; plausibility warnings shaded red.</source>
        <translation>Abbildung 5. Standphasendetektor C1/C2/C3 von %1 s bis %2 s: die Bedingungen C1, C2, C3, ihre Verknüpfung C, die mediangefilterte Standphase, die SD von |a| auf logarithmischer Achse und die Eingänge mit ihren Schwellwerten; Plausibilitätswarnungen rot schattiert.</translation>
    </message>
    <message>
        <source>Figure 5. Stance detector %3 from %1 s to %2 s: the condition C (statistic below threshold), the stance, and the statistic on a logarithmic axis with its threshold; plausibility warnings shaded red.</source>
        <translation>Abbildung 5. Standphasendetektor %3 von %1 s bis %2 s: die Bedingung C (Teststatistik unter dem Schwellwert), die Standphase und die Teststatistik auf logarithmischer Achse mit ihrem Schwellwert; Plausibilitätswarnungen rot schattiert.</translation>
    </message>
    <message>
        <source>Plausibility warnings</source>
        <translation>Plausibilitätswarnungen</translation>
    </message>
    <message>
        <source>The plausibility checks found nothing: the result looks like human gait.</source>
        <translation>Die Plausibilitätsprüfungen fanden nichts: das Ergebnis sieht nach menschlichem Gang aus.</translation>
    </message>
    <message>
        <source>Findings: %1. Each marks a span where the result is not what human gait gives, so the path needs care there.</source>
        <translation>Befunde: %1. Jeder markiert einen Zeitraum, in dem das Ergebnis nicht menschlichem Gang entspricht; dort ist der Weg mit Vorsicht zu lesen.</translation>
    </message>
    <message>
        <source>%1, %2: %3</source>
        <translation>%1, %2: %3</translation>
    </message>
    <message>
        <source>Import notes (reading the file)</source>
        <translation>Hinweise zum Import (Lesen der Datei)</translation>
    </message>
    <message>
        <source>Import warning: %1</source>
        <translation>Importwarnung: %1</translation>
    </message>
    <message>
        <source>Reading the file raised no warnings.</source>
        <translation>Beim Lesen der Datei gab es keine Warnungen.</translation>
    </message>
    <message>
        <source>Method comparison</source>
        <translation>Methodenvergleich</translation>
    </message>
    <message>
        <source>Every method set run on this recording with the same detector and noise parameters; the best value of a column is in bold and marked %1.</source>
        <translation>Jede Methodenkombination auf dieser Aufnahme mit denselben Detektor- und Rauschparametern gerechnet; der beste Wert einer Spalte ist fett und mit %1 markiert.</translation>
    </message>
    <message>
        <source>failed: %1</source>
        <translation>fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <source>no estimate</source>
        <translation>keine Schätzung</translation>
    </message>
    <message>
        <source>End to start
(m)</source>
        <translation>Ende bis Start
(m)</translation>
    </message>
    <message>
        <source>End to start
(%)</source>
        <translation>Ende bis Start
(%)</translation>
    </message>
    <message>
        <source>Path length
(m)</source>
        <translation>Weglänge
(m)</translation>
    </message>
    <message>
        <source>Height change
(m)</source>
        <translation>Höhenänderung
(m)</translation>
    </message>
    <message>
        <source>ARMSE 2D
(m)</source>
        <translation>ARMSE 2D
(m)</translation>
    </message>
    <message>
        <source>Stance F1</source>
        <translation>Standphasen-F1</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>Warnungen</translation>
    </message>
    <message>
        <source>Strides (turning)</source>
        <translation>Doppelschritte (Wenden)</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Stride time</source>
        <translation>Doppelschrittdauer</translation>
    </message>
    <message>
        <source>Stride length</source>
        <translation>Doppelschrittlänge</translation>
    </message>
    <message>
        <source>Cadence</source>
        <translation>Schrittfrequenz</translation>
    </message>
    <message>
        <source>Stance / swing</source>
        <translation>Standphase / Schwungphase</translation>
    </message>
    <message>
        <source>%1 % / %2 %</source>
        <translation>%1 % / %2 %</translation>
    </message>
    <message>
        <source>Foot clearance</source>
        <translation>Fußfreiheit</translation>
    </message>
    <message>
        <source>Double support (both feet on the ground)</source>
        <translation>Doppelstandphase (beide Füße am Boden)</translation>
    </message>
    <message>
        <source>%1 % of the gait cycle (initial %2 %, terminal %3 %), %4 strides</source>
        <translation>%1 % des Gangzyklus (initial %2 %, terminal %3 %), %4 Doppelschritte</translation>
    </message>
    <message>
        <source>Stance left / right</source>
        <translation>Standphase links / rechts</translation>
    </message>
    <message>
        <source>Symmetry index: stride time</source>
        <translation>Symmetrieindex: Doppelschrittdauer</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>Symmetry index: stride length</source>
        <translation>Symmetrieindex: Doppelschrittlänge</translation>
    </message>
    <message>
        <source>Symmetry index: stance</source>
        <translation>Symmetrieindex: Standphase</translation>
    </message>
    <message>
        <source>Symmetry index: swing</source>
        <translation>Symmetrieindex: Schwungphase</translation>
    </message>
    <message>
        <source>Gait (heel strike to toe off)</source>
        <translation>Gang (Fersenaufsatz bis Zehenablösung)</translation>
    </message>
    <message>
        <source>From the gait events of %1: means over the strides that neither turn (more than 20 degrees) nor pause.</source>
        <translation>Aus den Gangereignissen von %1: Mittelwerte über die Doppelschritte, die weder wenden (mehr als 20 Grad) noch pausieren.</translation>
    </message>
    <message>
        <source>the left foot</source>
        <translation>dem linken Fuß</translation>
    </message>
    <message>
        <source>this foot</source>
        <translation>diesem Fuß</translation>
    </message>
    <message>
        <source>Both feet</source>
        <translation>Beide Füße</translation>
    </message>
    <message>
        <source>The left and the right foot&apos;s files on one clock (their own time stamps). Symmetry index: 100 (left - right) / mean, 0 symmetric, positive where the left value is larger.</source>
        <translation>Die Dateien des linken und des rechten Fußes auf einer Uhr (ihre eigenen Zeitstempel). Symmetrieindex: 100 (links - rechts) / Mittelwert, 0 symmetrisch, positiv, wo der linke Wert größer ist.</translation>
    </message>
    <message>
        <source>Note: %1</source>
        <translation>Hinweis: %1</translation>
    </message>
    <message>
        <source>Figure 9. Gait stance (heel strike to toe off, left) and foot clearance (right) per stride.</source>
        <translation>Abbildung 9. Gang-Standphase (Fersenaufsatz bis Zehenablösung, links) und Fußfreiheit (rechts) je Doppelschritt.</translation>
    </message>
    <message>
        <source>stride</source>
        <translation>Doppelschritt</translation>
    </message>
    <message>
        <source>stance (% of the stride)</source>
        <translation>Standphase (% des Doppelschritts)</translation>
    </message>
    <message>
        <source>clearance (m)</source>
        <translation>Fußfreiheit (m)</translation>
    </message>
    <message>
        <source>Parameters (* and bold: differs from the default)</source>
        <translation>Parameter (* und fett: weicht vom Standardwert ab)</translation>
    </message>
    <message>
        <source>Figure 1. The foot path seen from above (reference dashed when present; the stances are too close together at this scale to be marked).</source>
        <translation>Abbildung 1. Der Weg des Fußes von oben (Referenz gestrichelt, falls vorhanden; die Standphasen liegen in diesem Maßstab zu dicht, um sie zu markieren).</translation>
    </message>
    <message>
        <source>Figure 3. The path in 3D (stance positions as dots; reference dashed when present).</source>
        <translation>Abbildung 3. Der Weg in 3D (Standphasen als Punkte; Referenz gestrichelt, falls vorhanden).</translation>
    </message>
    <message>
        <source>Figure 3. The path in 3D (reference dashed when present; the stances are too close together at this scale to be marked).</source>
        <translation>Abbildung 3. Der Weg in 3D (Referenz gestrichelt, falls vorhanden; die Standphasen liegen in diesem Maßstab zu dicht, um sie zu markieren).</translation>
    </message>
    <message>
        <source>%1 (%2 movements without a swing, under %3 m or %4 rad/s, merged into their stances)</source>
        <translation>%1 (%2 Bewegungen ohne Schwungphase, unter %3 m oder %4 rad/s, mit ihren Standphasen zusammengelegt)</translation>
    </message>
    <message>
        <source>Gait stance (heel strike to toe off) against the labels: precision / recall / F1</source>
        <translation>Gang-Standphase (Fersenaufsatz bis Zehenablösung) gegenüber den Markierungen: Präzision / Trefferquote / F1</translation>
    </message>
    <message>
        <source>Strides in the labelled trial</source>
        <translation>Doppelschritte im markierten Versuch</translation>
    </message>
    <message>
        <source>%1 detected, %2 labelled swings</source>
        <translation>%1 erkannt, %2 markierte Schwungphasen</translation>
    </message>
    <message>
        <source>Foot at rest (ZUPT) against the labelled stance: precision / recall / F1 (the foot rests only mid-stance: a low recall is expected)</source>
        <translation>Fuß in Ruhe (ZUPT) gegenüber der markierten Standphase: Präzision / Trefferquote / F1 (der Fuß ruht nur in der Mitte der Standphase: eine niedrige Trefferquote ist zu erwarten)</translation>
    </message>
    <message>
        <source>Method comparison (stale)</source>
        <translation>Methodenvergleich (veraltet)</translation>
    </message>
    <message>
        <source>Stale: the parameters changed after this comparison ran, so its rows were estimated with other parameters than the rest of this report. Run the comparison again to update it.</source>
        <translation>Veraltet: Die Parameter haben sich nach diesem Vergleich geändert, seine Zeilen wurden also mit anderen Parametern geschätzt als der Rest dieses Berichts. Den Vergleich erneut rechnen, um ihn zu aktualisieren.</translation>
    </message>
</context>
<context>
    <name>footpath::AnalysisSession</name>
    <message>
        <source>Change %1</source>
        <translation>%1 ändern</translation>
    </message>
</context>
<context>
    <name>footpath::ComparisonPanel</name>
    <message>
        <source>Method sets to compare; tick the ones to run</source>
        <translation>Zu vergleichende Methodenkombinationen; die zu rechnenden ankreuzen</translation>
    </message>
    <message>
        <source>Add a set, e.g. zupt,hdr,mag</source>
        <translation>Kombination hinzufügen, z. B. zupt,hdr,mag</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Rechnen</translation>
    </message>
    <message>
        <source>Run every ticked set on the current recording</source>
        <translation>Jede angekreuzte Kombination auf der aktuellen Aufnahme rechnen</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Click a row to make its methods the workspace&apos;s parameters (Edit &gt; Undo goes back)</source>
        <translation>Eine Zeile anklicken, um ihre Methoden als Parameter des Arbeitsbereichs zu übernehmen (Bearbeiten &gt; Rückgängig geht zurück)</translation>
    </message>
    <message>
        <source>Use as main result</source>
        <translation>Als Hauptergebnis verwenden</translation>
    </message>
    <message>
        <source>Make the selected set&apos;s methods the workspace&apos;s parameters</source>
        <translation>Die Methoden der gewählten Kombination als Parameter des Arbeitsbereichs übernehmen</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>height z (m)</source>
        <translation>Höhe z (m)</translation>
    </message>
    <message>
        <source>Tick at least one method set.</source>
        <translation>Mindestens eine Methodenkombination ankreuzen.</translation>
    </message>
    <message>
        <source>best</source>
        <translation>bester Wert</translation>
    </message>
    <message>
        <source>Stale: the parameters changed since this comparison. Run again to update it.</source>
        <translation>Veraltet: Die Parameter haben sich seit diesem Vergleich geändert. Erneut rechnen, um ihn zu aktualisieren.</translation>
    </message>
    <message>
        <source>Open a recording to compare methods on it.</source>
        <translation>Eine Aufnahme öffnen, um Methoden darauf zu vergleichen.</translation>
    </message>
    <message>
        <source>Tick the sets and press Run.</source>
        <translation>Kombinationen ankreuzen und Rechnen drücken.</translation>
    </message>
    <message>
        <source>Click a row to use its methods.</source>
        <translation>Eine Zeile anklicken, um ihre Methoden zu verwenden.</translation>
    </message>
    <message numerus="yes">
        <source>Running %n set(s)...</source>
        <translation>
            <numerusform>Rechne %n Kombination...</numerusform>
            <numerusform>Rechne %n Kombinationen...</numerusform>
        </translation>
    </message>
    <message>
        <source>Methods separated by commas: %1. Enter adds the set.</source>
        <translation>Methoden durch Kommas getrennt: %1. Eingabe fügt die Kombination hinzu.</translation>
    </message>
</context>
<context>
    <name>footpath::HelpDialog</name>
    <message>
        <source>Footpath help</source>
        <translation>Footpath-Hilfe</translation>
    </message>
    <message>
        <source>User guide</source>
        <translation>Benutzerhandbuch</translation>
    </message>
    <message>
        <source>Keyboard shortcuts</source>
        <translation>Tastenkürzel</translation>
    </message>
    <message>
        <source>Click</source>
        <translation>Klick</translation>
    </message>
    <message>
        <source>Plots and 2D path: move the time cursor there</source>
        <translation>Diagramme und 2D-Weg: die Zeitmarke dorthin setzen</translation>
    </message>
    <message>
        <source>Wheel</source>
        <translation>Mausrad</translation>
    </message>
    <message>
        <source>Plots: zoom the time axis; 3D: zoom about the pointer</source>
        <translation>Diagramme: Zeitachse zoomen; 3D: um den Mauszeiger zoomen</translation>
    </message>
    <message>
        <source>Drag</source>
        <translation>Ziehen</translation>
    </message>
    <message>
        <source>Plots and 2D path: pan; 3D: orbit (right or middle button: pan)</source>
        <translation>Diagramme und 2D-Weg: verschieben; 3D: drehen (rechte oder mittlere Taste: verschieben)</translation>
    </message>
    <message>
        <source>Ctrl+Wheel</source>
        <translation>Strg+Mausrad</translation>
    </message>
    <message>
        <source>Plots: zoom the value axis of the row under the pointer</source>
        <translation>Diagramme: die Werteachse der Zeile unter dem Mauszeiger zoomen</translation>
    </message>
    <message>
        <source>Wheel or drag on a value axis</source>
        <translation>Mausrad oder Ziehen auf einer Werteachse</translation>
    </message>
    <message>
        <source>Plots: zoom or pan that row&apos;s values</source>
        <translation>Diagramme: die Werte dieser Zeile zoomen oder verschieben</translation>
    </message>
    <message>
        <source>Pointer over a plot</source>
        <translation>Mauszeiger über einem Diagramm</translation>
    </message>
    <message>
        <source>Plots and 2D path: read the time and the values there</source>
        <translation>Diagramme und 2D-Weg: dort Zeit und Werte ablesen</translation>
    </message>
    <message>
        <source>Shift+Click</source>
        <translation>Umschalt+Klick</translation>
    </message>
    <message>
        <source>Plots and 2D path: set a marker; the readout then gives Δt and Δy from it</source>
        <translation>Diagramme und 2D-Weg: eine Markierung setzen; die Anzeige gibt dann Δt und Δy zu ihr an</translation>
    </message>
    <message>
        <source>Right-click</source>
        <translation>Rechtsklick</translation>
    </message>
    <message>
        <source>Plots: reset the view, export as PNG, SVG or PDF, or the visible data as CSV</source>
        <translation>Diagramme: Ansicht zurücksetzen, als PNG, SVG oder PDF exportieren, oder die sichtbaren Daten als CSV</translation>
    </message>
    <message>
        <source>Double-click</source>
        <translation>Doppelklick</translation>
    </message>
    <message>
        <source>Plots and paths: show everything again</source>
        <translation>Diagramme und Wege: wieder alles zeigen</translation>
    </message>
    <message>
        <source>Up / Down</source>
        <translation>Auf / Ab</translation>
    </message>
    <message>
        <source>Parameter value field: one slider step</source>
        <translation>Parameter-Wertefeld: ein Schieberegler-Schritt</translation>
    </message>
    <message>
        <source>Page Up / Page Down</source>
        <translation>Bild auf / Bild ab</translation>
    </message>
    <message>
        <source>Parameter value field: ten slider steps</source>
        <translation>Parameter-Wertefeld: zehn Schieberegler-Schritte</translation>
    </message>
    <message>
        <source>Step table: the next step, with the time cursor</source>
        <translation>Schritttabelle: der nächste Schritt, mit der Zeitmarke</translation>
    </message>
    <message>
        <source>Keys or mouse</source>
        <translation>Tasten oder Maus</translation>
    </message>
    <message>
        <source>Does</source>
        <translation>Bewirkt</translation>
    </message>
    <message>
        <source>&lt;h2&gt;Footpath in five minutes&lt;/h2&gt;&lt;p&gt;Footpath turns the recording of an inertial sensor on a shoe into the path walked: it finds the moments the foot rests on the ground (stance), integrates the motion in between, and corrects the drift with zero-velocity updates in a Kalman filter.&lt;/p&gt;&lt;h3&gt;Opening a recording&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;File &amp;gt; Open recording&lt;/b&gt;, the Recorded input panel, or drag a file onto the window. Xsens text exports, MT binary logs (.mtb), PyShoe CSV files and plain CSV/text with one sample per row are read.&lt;/li&gt;&lt;li&gt;A file that does not name its columns opens the import dialog: say which column holds what and in which unit; the dialog shows the first rows as they will be read.&lt;/li&gt;&lt;li&gt;The recording should start with about a second of standing still: the sensor&apos;s attitude is found from it.&lt;/li&gt;&lt;/ul&gt;&lt;h3&gt;What the views show&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Trajectory 2D / 3D&lt;/b&gt;: the path from above and in space. Orange dots are the stances, the green square is the start and the red cross the end, the yellow dot the time cursor; a dashed line is the reference when the file has one. After a parameter change the path before it stays as a faint grey ghost until the next change.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Signals&lt;/b&gt;: accelerometer, gyroscope and the other channels over time. The coloured lanes under them mark the stance phases (the foot at rest), plausibility warnings (red spans: a stride too long, a stance missed) and, with a barometer, the motion class of each step (level, stairs, elevator).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Stance detector&lt;/b&gt;: the statistic the detector thresholds and the threshold itself; where the curve is below the threshold the foot is taken to be at rest. A &lt;i&gt;Reference stance&lt;/i&gt; lane shows the stances the file&apos;s own labels give (gait events, motion capture), to compare with.&lt;/li&gt;&lt;li&gt;&lt;b&gt;States&lt;/b&gt;: the filter&apos;s attitude, velocity, height and sensor biases over time, with a band of one standard deviation where the filter estimates it.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Summary&lt;/b&gt;: the walk&apos;s figures (path length, strides, cadence, end-to-start distance), the figures against the reference when there is one, and a table of the steps. Selecting a step moves the time cursor to it in every view.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;One time cursor links every view: click a plot or the path and all views show that moment. Hold the pointer over a plot to read the values; Shift+click sets a marker to measure time and value differences from; right-click a plot to export it. &lt;b&gt;Help &amp;gt; Keyboard shortcuts&lt;/b&gt; lists every key.&lt;/p&gt;&lt;h3&gt;Tuning&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;The &lt;b&gt;Parameters&lt;/b&gt; panel lists every setting with its unit; the tool tip names the identifier used in presets and on the command line. A setting that has no effect with the others is greyed out, and its tool tip says why.&lt;/li&gt;&lt;li&gt;Every change re-estimates at once. The summary then shows the key figures before and after the change, green where the change helped and red where it hurt, and the &lt;b&gt;History&lt;/b&gt; lists the last runs: double-click one to go back to it. Undo (Ctrl+Z) goes back one change.&lt;/li&gt;&lt;li&gt;Presets save and load the whole set; &lt;b&gt;Analysis &amp;gt; Compare methods&lt;/b&gt; runs several method sets on the same recording side by side.&lt;/li&gt;&lt;/ul&gt;&lt;h3&gt;Live input&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;In the &lt;b&gt;Live input&lt;/b&gt; panel choose the sensor&apos;s serial port (or the emulator) and connect: the live path and signals appear in their own tabs while you walk.&lt;/li&gt;&lt;li&gt;Record writes the samples to a file (the name offered is the device&apos;s and the time&apos;s, in the folder of the last recording); when recording stops, the file opens for the full analysis. A session you did not record can still be saved after Disconnect.&lt;/li&gt;&lt;li&gt;A recording that starts while walking is still read: the path then starts at the first stance, and a warning says so.&lt;/li&gt;&lt;/ul&gt;&lt;h3&gt;Exporting&lt;/h3&gt;&lt;p&gt;&lt;b&gt;File &amp;gt; Export report&lt;/b&gt; writes a PDF with the figures, plots and parameters; &lt;b&gt;Export CSV&lt;/b&gt; writes the trajectory, steps, summary and parameters as CSV files.&lt;/p&gt;</source>
        <translation>&lt;h2&gt;Footpath in fünf Minuten&lt;/h2&gt;&lt;p&gt;Footpath macht aus der Aufzeichnung eines Inertialsensors an einem Schuh den gegangenen Weg: es findet die Momente, in denen der Fuß auf dem Boden ruht (Standphase), integriert die Bewegung dazwischen und korrigiert die Drift mit Nullgeschwindigkeits-Updates in einem Kalman-Filter.&lt;/p&gt;&lt;h3&gt;Eine Aufzeichnung öffnen&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Datei &amp;gt; Aufzeichnung öffnen&lt;/b&gt;, das Feld Aufzeichnung, oder eine Datei auf das Fenster ziehen. Gelesen werden Xsens-Textexporte, MT-Binärlogs (.mtb), PyShoe-CSV-Dateien und einfache CSV-/Textdateien mit einem Abtastwert je Zeile.&lt;/li&gt;&lt;li&gt;Eine Datei, die ihre Spalten nicht benennt, öffnet den Importdialog: geben Sie an, welche Spalte was in welcher Einheit enthält; der Dialog zeigt die ersten Zeilen so, wie sie gelesen werden.&lt;/li&gt;&lt;li&gt;Die Aufzeichnung sollte mit etwa einer Sekunde Stillstehen beginnen: daraus wird die Lage des Sensors bestimmt.&lt;/li&gt;&lt;/ul&gt;&lt;h3&gt;Was die Ansichten zeigen&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Trajektorie 2D / 3D&lt;/b&gt;: der Weg von oben und im Raum. Orange Punkte sind die Standphasen, das grüne Quadrat ist der Start und das rote Kreuz das Ende, der gelbe Punkt die Zeitmarke; eine gestrichelte Linie ist die Referenz, wenn die Datei eine hat. Nach einer Parameteränderung bleibt der vorherige Weg bis zur nächsten Änderung als blasser grauer Geist stehen.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Signale&lt;/b&gt;: Beschleunigungsmesser, Gyroskop und die übrigen Kanäle über der Zeit. Die farbigen Bahnen darunter markieren die Standphasen (der Fuß in Ruhe), Plausibilitätswarnungen (rote Zeitspannen: ein zu langer Doppelschritt, eine verpasste Standphase) und, mit Barometer, die Bewegungsart jedes Schritts (eben, Treppe, Aufzug).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Standphasendetektor&lt;/b&gt;: die Statistik, die der Detektor mit dem Schwellwert vergleicht, und der Schwellwert selbst; wo die Kurve unter dem Schwellwert liegt, gilt der Fuß als in Ruhe. Eine Bahn &lt;i&gt;Referenz-Standphase&lt;/i&gt; zeigt zum Vergleich die Standphasen, die die eigenen Markierungen der Datei angeben (Gangereignisse, Motion Capture).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Zustände&lt;/b&gt;: Lage, Geschwindigkeit, Höhe und Sensor-Biases des Filters über der Zeit, mit einem Band von einer Standardabweichung, wo das Filter sie schätzt.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Zusammenfassung&lt;/b&gt;: die Kennzahlen des Gangs (Weglänge, Doppelschritte, Schrittfrequenz, Abstand Ende–Start), die Kennzahlen gegenüber der Referenz, falls es eine gibt, und eine Tabelle der Schritte. Die Auswahl eines Schritts setzt die Zeitmarke in jeder Ansicht auf ihn.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Eine Zeitmarke verbindet alle Ansichten: ein Klick in ein Diagramm oder den Weg, und alle Ansichten zeigen diesen Moment. Halten Sie den Mauszeiger über ein Diagramm, um die Werte abzulesen; Umschalt+Klick setzt eine Markierung, von der aus Zeit- und Wertdifferenzen gemessen werden; ein Rechtsklick auf ein Diagramm exportiert es. &lt;b&gt;Hilfe &amp;gt; Tastenkürzel&lt;/b&gt; listet jede Taste auf.&lt;/p&gt;&lt;h3&gt;Abstimmen&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;Das Feld &lt;b&gt;Parameter&lt;/b&gt; listet jede Einstellung mit ihrer Einheit; der Tooltip nennt den Bezeichner, der in Voreinstellungen und auf der Kommandozeile verwendet wird. Eine Einstellung, die zusammen mit den anderen keine Wirkung hat, ist ausgegraut, und ihr Tooltip sagt warum.&lt;/li&gt;&lt;li&gt;Jede Änderung schätzt sofort neu. Die Zusammenfassung zeigt dann die wichtigsten Kennzahlen vor und nach der Änderung, grün, wo die Änderung geholfen hat, und rot, wo sie geschadet hat, und der &lt;b&gt;Verlauf&lt;/b&gt; listet die letzten Läufe: ein Doppelklick auf einen kehrt zu ihm zurück. Rückgängig (Strg+Z) geht eine Änderung zurück.&lt;/li&gt;&lt;li&gt;Voreinstellungen speichern und laden den ganzen Satz; &lt;b&gt;Analyse &amp;gt; Methoden vergleichen&lt;/b&gt; rechnet mehrere Methodenkombinationen nebeneinander auf derselben Aufzeichnung.&lt;/li&gt;&lt;/ul&gt;&lt;h3&gt;Live-Eingabe&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;Wählen Sie im Feld &lt;b&gt;Live-Eingabe&lt;/b&gt; die serielle Schnittstelle des Sensors (oder den Emulator) und verbinden Sie: Live-Weg und Live-Signale erscheinen in eigenen Reitern, während Sie gehen.&lt;/li&gt;&lt;li&gt;Aufzeichnen schreibt die Abtastwerte in eine Datei (der vorgeschlagene Name setzt sich aus Gerät und Uhrzeit zusammen, im Ordner der letzten Aufzeichnung); wenn die Aufzeichnung endet, öffnet sich die Datei zur vollständigen Analyse. Eine nicht aufgezeichnete Sitzung kann nach dem Trennen noch gespeichert werden.&lt;/li&gt;&lt;li&gt;Eine Aufzeichnung, die während des Gehens beginnt, wird trotzdem gelesen: der Weg beginnt dann bei der ersten Standphase, und eine Warnung weist darauf hin.&lt;/li&gt;&lt;/ul&gt;&lt;h3&gt;Exportieren&lt;/h3&gt;&lt;p&gt;&lt;b&gt;Datei &amp;gt; Bericht exportieren&lt;/b&gt; schreibt ein PDF mit den Kennzahlen, Diagrammen und Parametern; &lt;b&gt;CSV exportieren&lt;/b&gt; schreibt Trajektorie, Schritte, Zusammenfassung und Parameter als CSV-Dateien.&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>footpath::ImportDialog</name>
    <message>
        <source>How to read %1</source>
        <translation>%1 einlesen</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
    <message>
        <source>Import preset:</source>
        <translation>Importvoreinstellung:</translation>
    </message>
    <message>
        <source>detect</source>
        <translation>automatisch</translation>
    </message>
    <message>
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <source>g</source>
        <translation>g</translation>
    </message>
    <message>
        <source>rad/s</source>
        <translation>rad/s</translation>
    </message>
    <message>
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <source>µs</source>
        <translation>µs</translation>
    </message>
    <message>
        <source>Accelerometer unit:</source>
        <translation>Einheit Beschleunigungssensor:</translation>
    </message>
    <message>
        <source>Gyroscope unit:</source>
        <translation>Einheit Gyroskop:</translation>
    </message>
    <message>
        <source>Time unit:</source>
        <translation>Zeiteinheit:</translation>
    </message>
    <message>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <source>from the time column</source>
        <translation>aus der Zeitspalte</translation>
    </message>
    <message>
        <source>Sample rate:</source>
        <translation>Abtastrate:</translation>
    </message>
    <message>
        <source>Save as import preset named</source>
        <translation>Als Importvoreinstellung speichern unter</translation>
    </message>
    <message>
        <source>e.g. my-logger</source>
        <translation>z. B. my-logger</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Öffnen</translation>
    </message>
    <message>
        <source>role</source>
        <translation>Rolle</translation>
    </message>
    <message>
        <source>°/s</source>
        <translation>°/s</translation>
    </message>
    <message>
        <source>%1 needs import settings and no one is there to give them: %2</source>
        <translation>%1 benötigt Importeinstellungen, und niemand ist da, um sie anzugeben: %2</translation>
    </message>
    <message>
        <source>What each column holds (the first lines of the file below, numbered as in the file):</source>
        <translation>Was jede Spalte enthält (darunter die ersten Zeilen der Datei, nummeriert wie in der Datei):</translation>
    </message>
    <message>
        <source>column %1</source>
        <translation>Spalte %1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>Zeile %1</translation>
    </message>
    <message>
        <source>Line %1 is the file&apos;s header: its names title the columns, and the roles below replace it.</source>
        <translation>Zeile %1 ist die Kopfzeile der Datei: ihre Namen betiteln die Spalten, und die Rollen darunter ersetzen sie.</translation>
    </message>
    <message>
        <source>The file has no header row: say what each column holds.</source>
        <translation>Die Datei hat keine Kopfzeile: geben Sie an, was jede Spalte enthält.</translation>
    </message>
    <message>
        <source>Cannot be right: %1</source>
        <translation>Kann nicht stimmen: %1</translation>
    </message>
    <message>
        <source>Check: %1</source>
        <translation>Prüfen: %1</translation>
    </message>
    <message>
        <source>Read so, the first lines give: %1</source>
        <translation>So gelesen ergeben die ersten Zeilen: %1</translation>
    </message>
    <message>
        <source>From the values: %1</source>
        <translation>Aus den Werten: %1</translation>
    </message>
    <message>
        <source>Mend the roles or units first: the file cannot be read right so</source>
        <translation>Zuerst Rollen oder Einheiten korrigieren: so kann die Datei nicht richtig gelesen werden</translation>
    </message>
</context>
<context>
    <name>footpath::LivePanel</name>
    <message>
        <source>A serial port, or type a path such as the emulator&apos;s pseudo-terminal</source>
        <translation>Eine serielle Schnittstelle, oder geben Sie einen Pfad ein, etwa das Pseudo-Terminal des Emulators</translation>
    </message>
    <message>
        <source>Auto (probe)</source>
        <translation>Automatisch (erkennen)</translation>
    </message>
    <message>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Verbinden</translation>
    </message>
    <message>
        <source>Record...</source>
        <translation>Aufzeichnen...</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation>Schnittstelle:</translation>
    </message>
    <message>
        <source>Baud:</source>
        <translation>Baud:</translation>
    </message>
    <message>
        <source>Rate:</source>
        <translation>Rate:</translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>Nicht verbunden</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>Device ID:</source>
        <translation>Geräte-ID:</translation>
    </message>
    <message>
        <source>Product code:</source>
        <translation>Produktcode:</translation>
    </message>
    <message>
        <source>Firmware:</source>
        <translation>Firmware:</translation>
    </message>
    <message>
        <source>Counters</source>
        <translation>Zähler</translation>
    </message>
    <message>
        <source>Samples:</source>
        <translation>Abtastwerte:</translation>
    </message>
    <message>
        <source>Lost packets:</source>
        <translation>Verlorene Pakete:</translation>
    </message>
    <message>
        <source>Checksum errors:</source>
        <translation>Prüfsummenfehler:</translation>
    </message>
    <message>
        <source>Resyncs:</source>
        <translation>Neusynchronisierungen:</translation>
    </message>
    <message>
        <source>Recording to %1</source>
        <translation>Aufzeichnung nach %1</translation>
    </message>
    <message>
        <source>Recording starts when connected: %1</source>
        <translation>Aufzeichnung beginnt beim Verbinden: %1</translation>
    </message>
    <message>
        <source>Choose a port or type its path.</source>
        <translation>Wählen Sie eine Schnittstelle oder geben Sie ihren Pfad ein.</translation>
    </message>
    <message>
        <source>Record to</source>
        <translation>Aufzeichnen nach</translation>
    </message>
    <message>
        <source>Xsens MT binary (*.mtb)</source>
        <translation>Xsens-MT-Binärdatei (*.mtb)</translation>
    </message>
    <message>
        <source>Connecting...</source>
        <translation>Verbindung wird hergestellt...</translation>
    </message>
    <message>
        <source>Streaming</source>
        <translation>Datenstrom läuft</translation>
    </message>
    <message>
        <source>Stopping...</source>
        <translation>Wird beendet...</translation>
    </message>
    <message>
        <source>Recording stopped: %1</source>
        <translation>Aufzeichnung angehalten: %1</translation>
    </message>
    <message>
        <source>Recording saved to %1</source>
        <translation>Aufzeichnung gespeichert unter %1</translation>
    </message>
    <message>
        <source>Disconnected</source>
        <translation>Getrennt</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>Trennen</translation>
    </message>
    <message>
        <source>Stop recording</source>
        <translation>Aufzeichnung beenden</translation>
    </message>
    <message>
        <source>Estimate</source>
        <translation>Schätzung</translation>
    </message>
    <message>
        <source>Latency:</source>
        <translation>Latenz:</translation>
    </message>
    <message>
        <source>State:</source>
        <translation>Zustand:</translation>
    </message>
    <message>
        <source>Steps:</source>
        <translation>Schritte:</translation>
    </message>
    <message>
        <source>Distance:</source>
        <translation>Strecke:</translation>
    </message>
    <message>
        <source>No live estimate: %1</source>
        <translation>Keine Live-Schätzung: %1</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Waiting for samples</source>
        <translation>Warte auf Abtastwerte</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>Disconnected: the port went away.</source>
        <translation>Getrennt: die Schnittstelle ist verschwunden.</translation>
    </message>
    <message>
        <source>Complete: every sample estimated, as the offline analysis does</source>
        <translation>Fertig: jeder Abtastwert geschätzt, wie in der Offline-Analyse</translation>
    </message>
    <message>
        <source>The stance detector looks this far ahead (its windows are centred on each sample, and a stance is confirmed once it has lasted the minimum duration), so the estimate trails the sensor by up to this delay.</source>
        <translation>Der Standphasendetektor blickt so weit voraus (seine Fenster sind um jeden Abtastwert zentriert, und eine Standphase gilt erst nach ihrer Mindestdauer als bestätigt), daher folgt die Schätzung dem Sensor mit bis zu dieser Verzögerung.</translation>
    </message>
    <message>
        <source>Refresh the list of ports</source>
        <translation>Liste der Schnittstellen aktualisieren</translation>
    </message>
    <message>
        <source>Save...</source>
        <translation>Speichern...</translation>
    </message>
    <message>
        <source>Save the samples received in the last session (kept in memory) as a CSV file and open it as a recorded walk: for a session that was not recorded</source>
        <translation>Die in der letzten Sitzung empfangenen Abtastwerte (im Speicher gehalten) als CSV-Datei speichern und als aufgezeichneten Gang öffnen: für eine Sitzung, die nicht aufgezeichnet wurde</translation>
    </message>
    <message>
        <source>Horizontal distance from the start to where the foot is now</source>
        <translation>Horizontaler Abstand vom Start bis dorthin, wo der Fuß jetzt ist</translation>
    </message>
    <message>
        <source>Duration:</source>
        <translation>Dauer:</translation>
    </message>
    <message>
        <source>End to start:</source>
        <translation>Ende bis Start:</translation>
    </message>
    <message>
        <source>Warnings:</source>
        <translation>Warnungen:</translation>
    </message>
    <message>
        <source>Live session: %1</source>
        <translation>Live-Sitzung: %1</translation>
    </message>
    <message>
        <source>Samples saved to %1</source>
        <translation>Abtastwerte gespeichert unter %1</translation>
    </message>
    <message>
        <source>Save samples</source>
        <translation>Abtastwerte speichern</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>Unsaved samples</source>
        <translation>Nicht gespeicherte Abtastwerte</translation>
    </message>
    <message>
        <source>The last session&apos;s %1 samples were not recorded. Save them before connecting again?</source>
        <translation>Die %1 Abtastwerte der letzten Sitzung wurden nicht aufgezeichnet. Vor dem erneuten Verbinden speichern?</translation>
    </message>
    <message>
        <source>Not connected: choose a port and Connect (Live input panel)</source>
        <translation>Nicht verbunden: eine Schnittstelle wählen und Verbinden (Feld Live-Eingabe)</translation>
    </message>
    <message>
        <source>Not connected: %1</source>
        <translation>Nicht verbunden: %1</translation>
    </message>
    <message>
        <source>Connecting to %1...</source>
        <translation>Verbinde mit %1...</translation>
    </message>
    <message>
        <source>Connected: waiting for samples...</source>
        <translation>Verbunden: warte auf Abtastwerte...</translation>
    </message>
    <message>
        <source>Disconnected: the session failed</source>
        <translation>Getrennt: die Sitzung ist fehlgeschlagen</translation>
    </message>
    <message>
        <source>The connection failed.</source>
        <translation>Die Verbindung ist fehlgeschlagen.</translation>
    </message>
    <message>
        <source>Aligning: keep the foot still for %1 s (a walk already under way is aligned at its first stance)</source>
        <translation>Ausrichten: den Fuß %1 s still halten (ein bereits laufender Gang wird bei seiner ersten Standphase ausgerichtet)</translation>
    </message>
    <message>
        <source>Estimating (%1 s behind)</source>
        <translation>Schätzung läuft (%1 s zurück)</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Live: %1 steps, %2 m, %3 s, end to start %4 m, warnings: %5</source>
        <translation>Live: %1 Schritte, %2 m, %3 s, Ende bis Start %4 m, Warnungen: %5</translation>
    </message>
    <message>
        <source>Samples the views could not keep up with (the window was busy for longer than the display queue holds). They are in the recording all the same.</source>
        <translation>Messwerte, mit denen die Ansichten nicht Schritt halten konnten (das Fenster war länger beschäftigt, als die Anzeigewarteschlange fasst). Sie sind trotzdem in der Aufzeichnung.</translation>
    </message>
    <message>
        <source>Not shown:</source>
        <translation>Nicht angezeigt:</translation>
    </message>
    <message>
        <source>Re-estimating with the new parameters (the old estimate is shown meanwhile)</source>
        <translation>Neuschätzung mit den neuen Parametern (bis dahin wird die alte Schätzung angezeigt)</translation>
    </message>
    <message>
        <source>The %1 samples received before the port went away were not recorded. Reconnecting starts a new session without them. Save them before reconnecting?</source>
        <translation>Die %1 Abtastwerte, die vor dem Verschwinden der Schnittstelle empfangen wurden, wurden nicht aufgezeichnet. Neu verbinden beginnt eine neue Sitzung ohne sie. Vor dem Neuverbinden speichern?</translation>
    </message>
    <message>
        <source>The live session&apos;s %1 samples were not recorded. Save them before quitting?</source>
        <translation>Die %1 Abtastwerte der Live-Sitzung wurden nicht aufgezeichnet. Vor dem Beenden speichern?</translation>
    </message>
</context>
<context>
    <name>footpath::LiveViews</name>
    <message>
        <source>Live 2D</source>
        <translation>Live 2D</translation>
    </message>
    <message>
        <source>Live 3D</source>
        <translation>Live 3D</translation>
    </message>
    <message>
        <source>live</source>
        <translation>live</translation>
    </message>
    <message>
        <source>The live session&apos;s path seen from above, as it grows</source>
        <translation>Der Weg der Live-Sitzung von oben gesehen, während er wächst</translation>
    </message>
    <message>
        <source>The live session&apos;s path in three dimensions, as it grows</source>
        <translation>Der Weg der Live-Sitzung in drei Dimensionen, während er wächst</translation>
    </message>
    <message>
        <source>Live IMU</source>
        <translation>Live-IMU</translation>
    </message>
    <message>
        <source>Live signals: the live session&apos;s last seconds of sensor signals</source>
        <translation>Live-Signale: die letzten Sekunden der Sensorsignale der Live-Sitzung</translation>
    </message>
    <message>
        <source>Live stance</source>
        <translation>Live-Standphase</translation>
    </message>
    <message>
        <source>Live stance detector: the live session&apos;s detector over its last seconds</source>
        <translation>Live-Standphasendetektor: der Detektor der Live-Sitzung über ihre letzten Sekunden</translation>
    </message>
</context>
<context>
    <name>footpath::MainWindow</name>
    <message>
        <source>Path &amp;colours</source>
        <translation>Pfad&amp;farben</translation>
    </message>
    <message>
        <source>One colour</source>
        <translation>Eine Farbe</translation>
    </message>
    <message>
        <source>By time</source>
        <translation>Nach Zeit</translation>
    </message>
    <message>
        <source>By foot speed</source>
        <translation>Nach Fußgeschwindigkeit</translation>
    </message>
    <message>
        <source>By motion (stairs, elevator)</source>
        <translation>Nach Bewegung (Treppe, Aufzug)</translation>
    </message>
    <message>
        <source>Footpath</source>
        <translation>Footpath</translation>
    </message>
    <message>
        <source>Ready</source>
        <translation>Bereit</translation>
    </message>
    <message>
        <source>Signals</source>
        <translation>Signale</translation>
    </message>
    <message>
        <source>Stance detector</source>
        <translation>Standphasendetektor</translation>
    </message>
    <message>
        <source>Trajectory 2D</source>
        <translation>Trajektorie 2D</translation>
    </message>
    <message>
        <source>Trajectory 3D</source>
        <translation>Trajektorie 3D</translation>
    </message>
    <message>
        <source>Recorded input</source>
        <translation>Aufzeichnung</translation>
    </message>
    <message>
        <source>Live input</source>
        <translation>Live-Eingabe</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Summary</source>
        <translation>Zusammenfassung</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;About Footpath</source>
        <translation>Ü&amp;ber Footpath</translation>
    </message>
    <message>
        <source>About Footpath</source>
        <translation>Über Footpath</translation>
    </message>
    <message>
        <source>&lt;b&gt;Footpath %1&lt;/b&gt;&lt;p&gt;Foot-mounted inertial navigation: stance detection, strapdown mechanization and an error-state Kalman filter with zero-velocity updates (Guo et al. 2015).&lt;/p&gt;&lt;p&gt;Sample walk: PyShoe VICON dataset, MIT licence, Copyright (c) 2024 Tā-Hā.&lt;/p&gt;</source>
        <translation>&lt;b&gt;Footpath %1&lt;/b&gt;&lt;p&gt;Fußmontierte Inertialnavigation: Standphasenerkennung, Strapdown-Mechanisierung und ein Error-State-Kalman-Filter mit Nullgeschwindigkeits-Updates (ZUPT) (Guo et al. 2015).&lt;/p&gt;&lt;p&gt;Beispielgang: PyShoe-VICON-Datensatz, MIT-Lizenz, Copyright (c) 2024 Tā-Hā.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;Open recording...</source>
        <translation>Aufzeichnung ö&amp;ffnen...</translation>
    </message>
    <message>
        <source>Open with &amp;import settings...</source>
        <translation>Mit &amp;Importeinstellungen öffnen...</translation>
    </message>
    <message>
        <source>Open recording</source>
        <translation>Aufzeichnung öffnen</translation>
    </message>
    <message>
        <source>Say how to read this file.</source>
        <translation>Geben Sie an, wie diese Datei zu lesen ist.</translation>
    </message>
    <message>
        <source>Export &amp;report (PDF)...</source>
        <translation>Be&amp;richt exportieren (PDF)...</translation>
    </message>
    <message>
        <source>Export &amp;CSV...</source>
        <translation>&amp;CSV exportieren...</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig:</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederherstellen:</translation>
    </message>
    <message>
        <source>Reset parameters to &amp;defaults</source>
        <translation>Parameter auf &amp;Standardwerte zurücksetzen</translation>
    </message>
    <message>
        <source>Reset to defaults</source>
        <translation>Auf Standardwerte zurücksetzen</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Trajectory 2D</source>
        <translation>&amp;Trajektorie 2D</translation>
    </message>
    <message>
        <source>Trajectory &amp;3D</source>
        <translation>Trajektorie &amp;3D</translation>
    </message>
    <message>
        <source>&amp;Signals</source>
        <translation>&amp;Signale</translation>
    </message>
    <message>
        <source>Stance &amp;detector</source>
        <translation>Standphasen&amp;detektor</translation>
    </message>
    <message>
        <source>&amp;Settings</source>
        <translation>&amp;Einstellungen</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <source>System default</source>
        <translation>Systemstandard</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Sprache</translation>
    </message>
    <message>
        <source>The new language is used from the next start of Footpath.</source>
        <translation>Die neue Sprache gilt ab dem nächsten Start von Footpath.</translation>
    </message>
    <message>
        <source>Loading cancelled.</source>
        <translation>Laden abgebrochen.</translation>
    </message>
    <message>
        <source>Estimate failed: %1</source>
        <translation>Schätzung fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>defaults</source>
        <translation>Standardwerte</translation>
    </message>
    <message>
        <source>adjusted in the window</source>
        <translation>im Fenster angepasst</translation>
    </message>
    <message>
        <source>Export report</source>
        <translation>Bericht exportieren</translation>
    </message>
    <message>
        <source>There is no estimate to report yet.</source>
        <translation>Es gibt noch keine Schätzung für einen Bericht.</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Report written to %1</source>
        <translation>Bericht gespeichert: %1</translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation>CSV exportieren</translation>
    </message>
    <message>
        <source>There is no estimate to export yet.</source>
        <translation>Es gibt noch keine Schätzung zum Exportieren.</translation>
    </message>
    <message>
        <source>Export CSV into folder</source>
        <translation>CSV in Ordner exportieren</translation>
    </message>
    <message>
        <source>Trajectory, steps, summary and parameters written to %1</source>
        <translation>Trajektorie, Schritte, Zusammenfassung und Parameter gespeichert in %1</translation>
    </message>
    <message>
        <source>Reading %1...</source>
        <translation>%1 wird gelesen...</translation>
    </message>
    <message>
        <source>Footpath - %1</source>
        <translation>Footpath - %1</translation>
    </message>
    <message>
        <source>%1 samples, %2 steps, path %3 m, end to start %4 m (%5 %), estimated in %6 ms</source>
        <translation>%1 Abtastwerte, %2 Schritte, Weg %3 m, Ende–Start %4 m (%5 %), geschätzt in %6 ms</translation>
    </message>
    <message>
        <source>Estimating...</source>
        <translation>Schätzung läuft...</translation>
    </message>
    <message>
        <source>&amp;Live path</source>
        <translation>&amp;Live-Weg</translation>
    </message>
    <message>
        <source>Live si&amp;gnals</source>
        <translation>Live-Si&amp;gnale</translation>
    </message>
    <message numerus="yes">
        <source>%n plausibility warning(s): %1</source>
        <translation>
            <numerusform>%n Plausibilitätswarnung: %1</numerusform>
            <numerusform>%n Plausibilitätswarnungen: %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Method comparison</source>
        <translation>Methodenvergleich</translation>
    </message>
    <message>
        <source>&amp;Compare methods</source>
        <translation>Methoden &amp;vergleichen</translation>
    </message>
    <message>
        <source>Run several method sets on this recording and compare their paths and figures</source>
        <translation>Mehrere Methodenkombinationen auf dieser Aufnahme rechnen und ihre Wege und Kennzahlen vergleichen</translation>
    </message>
    <message>
        <source>Compare</source>
        <translation>Vergleichen</translation>
    </message>
    <message>
        <source>Methods of the set %1</source>
        <translation>Methoden der Kombination %1</translation>
    </message>
    <message>
        <source>&amp;Analysis</source>
        <translation>&amp;Analyse</translation>
    </message>
    <message>
        <source>IMU</source>
        <translation>IMU</translation>
    </message>
    <message>
        <source>Signals: the recorded walk&apos;s sensor signals</source>
        <translation>Signale: die Sensorsignale des aufgezeichneten Gangs</translation>
    </message>
    <message>
        <source>Stance</source>
        <translation>Standphase</translation>
    </message>
    <message>
        <source>Stance detector: the recorded walk&apos;s statistics, thresholds, lanes</source>
        <translation>Standphasendetektor: Statistiken, Schwellwerte und Bahnen des aufgezeichneten Gangs</translation>
    </message>
    <message>
        <source>States</source>
        <translation>Zustände</translation>
    </message>
    <message>
        <source>States: the recorded walk&apos;s attitude, velocity, biases</source>
        <translation>Zustände: Lage, Geschwindigkeit und Biases des aufgezeichneten Gangs</translation>
    </message>
    <message>
        <source>2D</source>
        <translation>2D</translation>
    </message>
    <message>
        <source>Trajectory 2D: the recorded walk&apos;s path seen from above</source>
        <translation>Trajektorie 2D: der Weg des aufgezeichneten Gangs von oben gesehen</translation>
    </message>
    <message>
        <source>3D</source>
        <translation>3D</translation>
    </message>
    <message>
        <source>Trajectory 3D: the recorded walk&apos;s path in three dimensions</source>
        <translation>Trajektorie 3D: der Weg des aufgezeichneten Gangs in drei Dimensionen</translation>
    </message>
    <message>
        <source>History</source>
        <translation>Verlauf</translation>
    </message>
    <message>
        <source>&amp;User guide</source>
        <translation>&amp;Benutzerhandbuch</translation>
    </message>
    <message>
        <source>&amp;Keyboard shortcuts</source>
        <translation>&amp;Tastenkürzel</translation>
    </message>
    <message>
        <source>Undo the last change</source>
        <translation>Die letzte Änderung rückgängig machen</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Wiederherstellen</translation>
    </message>
    <message>
        <source>S&amp;tates</source>
        <translation>&amp;Zustände</translation>
    </message>
    <message>
        <source>Back to run %1</source>
        <translation>Zurück zu Lauf %1</translation>
    </message>
    <message>
        <source>Left foot</source>
        <translation>Linker Fuß</translation>
    </message>
    <message>
        <source>&amp;Tune for this recording...</source>
        <translation>Für diese Aufzeichnung &amp;optimieren...</translation>
    </message>
    <message>
        <source>Search the detector settings and the filter noise that fit this recording best</source>
        <translation>Die Detektoreinstellungen und das Filterrauschen suchen, die am besten zu dieser Aufzeichnung passen</translation>
    </message>
    <message>
        <source>Tune over a &amp;folder...</source>
        <translation>Über einen &amp;Ordner optimieren...</translation>
    </message>
    <message>
        <source>One parameter set for many recordings of a sensor and a way of walking</source>
        <translation>Ein Parametersatz für viele Aufzeichnungen eines Sensors und einer Gangart</translation>
    </message>
    <message>
        <source>Tune for this recording</source>
        <translation>Für diese Aufzeichnung optimieren</translation>
    </message>
    <message>
        <source>Open a recording first.</source>
        <translation>Öffnen Sie zuerst eine Aufzeichnung.</translation>
    </message>
    <message>
        <source>Right foot</source>
        <translation>Rechter Fuß</translation>
    </message>
    <message>
        <source>Open recording (two files: both feet)</source>
        <translation>Aufzeichnung öffnen (zwei Dateien: beide Füße)</translation>
    </message>
    <message>
        <source>%1 files: open one recording, or the left and the right file of one walk</source>
        <translation>%1 Dateien: eine Aufzeichnung öffnen, oder die linke und die rechte Datei eines Gangs</translation>
    </message>
    <message>
        <source>Footpath - %1 + %2</source>
        <translation>Footpath - %1 + %2</translation>
    </message>
    <message>
        <source>unknown view &apos;%1&apos;%2; the views are %3</source>
        <translation>unbekannte Ansicht &apos;%1&apos;%2; die Ansichten sind %3</translation>
    </message>
    <message>
        <source>Trajectory, steps and summary of both feet, and the parameters, written to %1</source>
        <translation>Trajektorie, Schritte und Zusammenfassung beider Füße sowie die Parameter gespeichert in %1</translation>
    </message>
    <message>
        <source>Recordings (%1);;All files (*)</source>
        <translation>Aufzeichnungen (%1);;Alle Dateien (*)</translation>
    </message>
</context>
<context>
    <name>footpath::MotionLanes</name>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;: steps %2–%3 (%4–%5 s)</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;: Schritte %2–%3 (%4–%5 s)</translation>
    </message>
    <message>
        <source>&lt;br&gt;barometric height %1 → %2 m</source>
        <translation>&lt;br&gt;barometrische Höhe %1 → %2 m</translation>
    </message>
    <message>
        <source>Level</source>
        <translation>Eben</translation>
    </message>
    <message>
        <source>Stairs up</source>
        <translation>Treppe hinauf</translation>
    </message>
    <message>
        <source>Stairs down</source>
        <translation>Treppe hinab</translation>
    </message>
    <message>
        <source>Elevator up</source>
        <translation>Aufzug hinauf</translation>
    </message>
    <message>
        <source>Elevator down</source>
        <translation>Aufzug hinab</translation>
    </message>
    <message>
        <source>Unclassified</source>
        <translation>Ohne Klasse</translation>
    </message>
    <message>
        <source>1 floor up by stairs (%1 m)</source>
        <translation>1 Stockwerk über die Treppe hinauf (%1 m)</translation>
    </message>
    <message>
        <source>1 floor down by stairs (%1 m)</source>
        <translation>1 Stockwerk über die Treppe hinab (%1 m)</translation>
    </message>
    <message>
        <source>%1 floors up by stairs (%2 m)</source>
        <translation>%1 Stockwerke über die Treppe hinauf (%2 m)</translation>
    </message>
    <message>
        <source>%1 floors down by stairs (%2 m)</source>
        <translation>%1 Stockwerke über die Treppe hinab (%2 m)</translation>
    </message>
    <message>
        <source>%1 m up by stairs</source>
        <translation>%1 m über die Treppe hinauf</translation>
    </message>
    <message>
        <source>%1 m down by stairs</source>
        <translation>%1 m über die Treppe hinab</translation>
    </message>
    <message>
        <source>1 elevator ride</source>
        <translation>1 Aufzugfahrt</translation>
    </message>
    <message>
        <source>%1 elevator rides</source>
        <translation>%1 Aufzugfahrten</translation>
    </message>
    <message>
        <source>Level walking only: no stairs or elevator</source>
        <translation>Nur ebenes Gehen: keine Treppe, kein Aufzug</translation>
    </message>
    <message>
        <source>Feliz integrator</source>
        <translation>Feliz-Integrator</translation>
    </message>
    <message>
        <source>%1–%2 s</source>
        <translation>%1–%2 s</translation>
    </message>
    <message>
        <source>%1, %2: %3</source>
        <translation>%1, %2: %3</translation>
    </message>
    <message>
        <source>Motion</source>
        <translation>Bewegung</translation>
    </message>
    <message>
        <source>Method notes</source>
        <translation>Hinweise der Verfahren</translation>
    </message>
    <message>
        <source>barometer present, steps not classified (use_baro off?)</source>
        <translation>Barometer vorhanden, Schritte nicht eingeordnet (use_baro aus?)</translation>
    </message>
    <message>
        <source>Colour by motion</source>
        <translation>Nach Bewegung färben</translation>
    </message>
    <message>
        <source>Colour each stride by its step&apos;s motion class (stairs, elevator); needs a barometer</source>
        <translation>Jeden Schritt nach seiner Bewegungsklasse färben (Treppe, Aufzug); braucht ein Barometer</translation>
    </message>
    <message>
        <source>Baro height (m)</source>
        <translation>Baro-Höhe (m)</translation>
    </message>
    <message>
        <source>How the foot got to this step: level, stairs or elevator (from the barometer)</source>
        <translation>Wie der Fuß zu diesem Schritt kam: eben, Treppe oder Aufzug (aus dem Barometer)</translation>
    </message>
    <message>
        <source>Barometric height at this stance against the first one</source>
        <translation>Barometrische Höhe in dieser Standphase gegenüber der ersten</translation>
    </message>
    <message>
        <source>Counted from the barometer&apos;s height between steps (Zheng et al. 2016); a floor is 3 m</source>
        <translation>Gezählt aus der Barometerhöhe zwischen den Schritten (Zheng et al. 2016); ein Stockwerk sind 3 m</translation>
    </message>
    <message>
        <source>Where a measurement method skipped itself or did not apply, and why</source>
        <translation>Wo ein Messverfahren sich ausgesetzt hat oder nicht anwendbar war, und warum</translation>
    </message>
    <message>
        <source>&lt;b&gt;Motion&lt;/b&gt; (barometer): %1</source>
        <translation>&lt;b&gt;Bewegung&lt;/b&gt; (Barometer): %1</translation>
    </message>
    <message>
        <source>Spans where a measurement method skipped itself or did not apply, and why; the other methods ran on.</source>
        <translation>Zeitspannen, in denen ein Messverfahren sich ausgesetzt hat oder nicht anwendbar war, und warum; die übrigen Verfahren liefen weiter.</translation>
    </message>
    <message>
        <source>Motion (barometer): %1.</source>
        <translation>Bewegung (Barometer): %1.</translation>
    </message>
</context>
<context>
    <name>footpath::OtherFootSession</name>
    <message>
        <source>%1 (the right foot): %2</source>
        <translation>%1 (der rechte Fuß): %2</translation>
    </message>
    <message>
        <source>The right foot&apos;s estimate failed: %1</source>
        <translation>Die Schätzung des rechten Fußes ist fehlgeschlagen: %1</translation>
    </message>
</context>
<context>
    <name>footpath::ParameterFields</name>
    <message>
        <source>Alignment period</source>
        <translation>Ausrichtungsdauer</translation>
    </message>
    <message>
        <source>Static period at the start used for alignment</source>
        <translation>Ruhephase zu Beginn, die zur Ausrichtung dient</translation>
    </message>
    <message>
        <source>Alignment</source>
        <translation>Ausrichtung</translation>
    </message>
    <message>
        <source>Gravity</source>
        <translation>Schwerebeschleunigung</translation>
    </message>
    <message>
        <source>Local gravity</source>
        <translation>Lokale Schwerebeschleunigung</translation>
    </message>
    <message>
        <source>Magnetic declination</source>
        <translation>Magnetische Deklination</translation>
    </message>
    <message>
        <source>Magnetic declination subtracted from the compass heading</source>
        <translation>Magnetische Deklination, die vom Kompasskurs abgezogen wird</translation>
    </message>
    <message>
        <source>Stance detector</source>
        <translation>Standphasendetektor</translation>
    </message>
    <message>
        <source>C1/C2/C3 (Guo 2015)</source>
        <translation>C1/C2/C3 (Guo 2015)</translation>
    </message>
    <message>
        <source>SHOE (GLRT)</source>
        <translation>SHOE (GLRT)</translation>
    </message>
    <message>
        <source>ARED (angular rate energy)</source>
        <translation>ARED (Drehratenenergie)</translation>
    </message>
    <message>
        <source>AMVD (acceleration variance)</source>
        <translation>AMVD (Beschleunigungsvarianz)</translation>
    </message>
    <message>
        <source>MBGTD (graph theoretic)</source>
        <translation>MBGTD (graphentheoretisch)</translation>
    </message>
    <message>
        <source>Statistic that decides the foot is at rest</source>
        <translation>Statistik, die entscheidet, ob der Fuß ruht</translation>
    </message>
    <message>
        <source>Detector</source>
        <translation>Detektor</translation>
    </message>
    <message>
        <source>Statistic window</source>
        <translation>Statistikfenster</translation>
    </message>
    <message>
        <source>Window of the detector statistic</source>
        <translation>Fenster der Detektorstatistik</translation>
    </message>
    <message>
        <source>Accelerometer noise</source>
        <translation>Rauschen Beschleunigungssensor</translation>
    </message>
    <message>
        <source>Accelerometer noise the statistic is normalised by</source>
        <translation>Rauschen des Beschleunigungssensors, auf das die Statistik normiert wird</translation>
    </message>
    <message>
        <source>Gyroscope noise</source>
        <translation>Rauschen Gyroskop</translation>
    </message>
    <message>
        <source>Gyroscope noise the statistic is normalised by</source>
        <translation>Rauschen des Gyroskops, auf das die Statistik normiert wird</translation>
    </message>
    <message>
        <source>Adaptive threshold</source>
        <translation>Adaptiver Schwellwert</translation>
    </message>
    <message>
        <source>Threshold follows the motion (off: a fixed threshold)</source>
        <translation>Schwellwert folgt der Bewegung (aus: fester Schwellwert)</translation>
    </message>
    <message>
        <source>Fixed threshold</source>
        <translation>Fester Schwellwert</translation>
    </message>
    <message>
        <source>Fixed threshold on the statistic (log10), when not adaptive</source>
        <translation>Fester Schwellwert der Statistik (log10), wenn nicht adaptiv</translation>
    </message>
    <message>
        <source>Adaptive window</source>
        <translation>Adaptives Fenster</translation>
    </message>
    <message>
        <source>Adaptive: window of the running minimum (about one gait cycle)</source>
        <translation>Adaptiv: Fenster des gleitenden Minimums (etwa ein Gangzyklus)</translation>
    </message>
    <message>
        <source>Offset above the minimum</source>
        <translation>Abstand über dem Minimum</translation>
    </message>
    <message>
        <source>Adaptive: threshold above the running minimum</source>
        <translation>Adaptiv: Schwellwert über dem gleitenden Minimum</translation>
    </message>
    <message>
        <source>Fraction towards the maximum</source>
        <translation>Anteil zum Maximum hin</translation>
    </message>
    <message>
        <source>Adaptive: threshold this fraction of the way from the running minimum to the maximum</source>
        <translation>Adaptiv: Schwellwert bei diesem Anteil des Abstands vom gleitenden Minimum zum Maximum</translation>
    </message>
    <message>
        <source>Always at rest below</source>
        <translation>Immer in Ruhe unterhalb</translation>
    </message>
    <message>
        <source>Adaptive: below this the foot is always at rest</source>
        <translation>Adaptiv: darunter ist der Fuß immer in Ruhe</translation>
    </message>
    <message>
        <source>Never at rest above</source>
        <translation>Nie in Ruhe oberhalb</translation>
    </message>
    <message>
        <source>Adaptive: above this the foot is never at rest</source>
        <translation>Adaptiv: darüber ist der Fuß nie in Ruhe</translation>
    </message>
    <message>
        <source>Shortest stance</source>
        <translation>Kürzeste Standphase</translation>
    </message>
    <message>
        <source>Shorter stance runs are dropped</source>
        <translation>Kürzere Standphasen werden verworfen</translation>
    </message>
    <message>
        <source>C1 lower bound on |a|</source>
        <translation>C1 Untergrenze für |a|</translation>
    </message>
    <message>
        <source>C1: lower bound on |a|</source>
        <translation>C1: Untergrenze für |a|</translation>
    </message>
    <message>
        <source>C1 upper bound on |a|</source>
        <translation>C1 Obergrenze für |a|</translation>
    </message>
    <message>
        <source>C1: upper bound on |a|</source>
        <translation>C1: Obergrenze für |a|</translation>
    </message>
    <message>
        <source>C2 bound on the std of |a|</source>
        <translation>C2 Grenze für die SD von |a|</translation>
    </message>
    <message>
        <source>C2: std of |a| over the window must be below</source>
        <translation>C2: die SD von |a| über das Fenster muss darunter liegen</translation>
    </message>
    <message>
        <source>C2 half-window</source>
        <translation>C2 Halbfenster</translation>
    </message>
    <message>
        <source>C2: half-window of the centred std</source>
        <translation>C2: Halbfenster der zentrierten SD</translation>
    </message>
    <message>
        <source>C3 bound on |ω|</source>
        <translation>C3 Grenze für |ω|</translation>
    </message>
    <message>
        <source>C3: upper bound on |w|</source>
        <translation>C3: Obergrenze für |w|</translation>
    </message>
    <message>
        <source>Median filter length</source>
        <translation>Medianfilterlänge</translation>
    </message>
    <message>
        <source>Median filter length applied to C</source>
        <translation>Länge des auf C angewandten Medianfilters</translation>
    </message>
    <message>
        <source>Filter states</source>
        <translation>Filterzustände</translation>
    </message>
    <message>
        <source>15 states (with biases)</source>
        <translation>15 Zustände (mit Biases)</translation>
    </message>
    <message>
        <source>9 states (no bias states)</source>
        <translation>9 Zustände (ohne Bias-Zustände)</translation>
    </message>
    <message>
        <source>Error-state filter size: 15 estimates the sensor biases, 9 holds them at zero</source>
        <translation>Größe des Error-State-Filters: 15 schätzt die Sensor-Biases, 9 hält sie bei null</translation>
    </message>
    <message>
        <source>Filter</source>
        <translation>Filter</translation>
    </message>
    <message>
        <source>Estimator</source>
        <translation>Schätzer</translation>
    </message>
    <message>
        <source>Kalman filter</source>
        <translation>Kalman-Filter</translation>
    </message>
    <message>
        <source>Feliz de-drift (no filter)</source>
        <translation>Feliz-Driftkorrektur (ohne Filter)</translation>
    </message>
    <message>
        <source>Kalman filter + RTS smoother</source>
        <translation>Kalman-Filter + RTS-Glätter</translation>
    </message>
    <message>
        <source>Kalman filter with the measurements below, Feliz 2009&apos;s per-stride velocity de-drift, or the filter followed by a Rauch-Tung-Striebel smoother over the whole recording (offline; live input runs the filter)</source>
        <translation>Kalman-Filter mit den Messungen unten, die Geschwindigkeits-Driftkorrektur je Doppelschritt nach Feliz 2009, oder das Filter gefolgt von einem Rauch-Tung-Striebel-Glätter über die ganze Aufzeichnung (offline; die Live-Eingabe rechnet das Filter)</translation>
    </message>
    <message>
        <source>Measurements</source>
        <translation>Messungen</translation>
    </message>
    <message>
        <source>Zero-velocity update (ZUPT)</source>
        <translation>Nullgeschwindigkeits-Update (ZUPT)</translation>
    </message>
    <message>
        <source>Zero-velocity update during stance</source>
        <translation>Nullgeschwindigkeits-Update während der Standphase</translation>
    </message>
    <message>
        <source>Zero angular rate update (ZARU)</source>
        <translation>Null-Drehraten-Update (ZARU)</translation>
    </message>
    <message>
        <source>Zero angular rate update during stance</source>
        <translation>Null-Drehraten-Update während der Standphase</translation>
    </message>
    <message>
        <source>Heuristic drift reduction (HDR)</source>
        <translation>Heuristische Driftreduktion (HDR)</translation>
    </message>
    <message>
        <source>Heuristic drift reduction: heading held on straight walks</source>
        <translation>Heuristische Driftreduktion: Kurs auf geraden Strecken gehalten</translation>
    </message>
    <message>
        <source>Position error reduction (IPER)</source>
        <translation>Positionsfehlerreduktion (IPER)</translation>
    </message>
    <message>
        <source>Position error reduction: walks along the building&apos;s axes, level floor (assumes a rectilinear building)</source>
        <translation>Positionsfehlerreduktion: Gehen entlang der Gebäudeachsen, ebener Boden (setzt ein rechtwinkliges Gebäude voraus)</translation>
    </message>
    <message>
        <source>Zero navigation acceleration (ZUNA)</source>
        <translation>Null-Navigationsbeschleunigung (ZUNA)</translation>
    </message>
    <message>
        <source>Zero navigation acceleration at mid-stance</source>
        <translation>Null-Navigationsbeschleunigung in der Mitte der Standphase</translation>
    </message>
    <message>
        <source>Barometric height</source>
        <translation>Barometrische Höhe</translation>
    </message>
    <message>
        <source>Barometric height at each stance (Zheng et al. 2016)</source>
        <translation>Barometrische Höhe in jeder Standphase (Zheng et al. 2016)</translation>
    </message>
    <message>
        <source>Magnetometer heading</source>
        <translation>Magnetometer-Kurs</translation>
    </message>
    <message>
        <source>Magnetometer heading during stance, skipped near steel</source>
        <translation>Magnetometer-Kurs während der Standphase, in der Nähe von Stahl ausgelassen</translation>
    </message>
    <message>
        <source>HDR heading lag</source>
        <translation>HDR-Kursverzögerung</translation>
    </message>
    <message>
        <source>HDR: heading compared with the heading this long ago</source>
        <translation>HDR: Kurs verglichen mit dem Kurs vor dieser Zeitspanne</translation>
    </message>
    <message>
        <source>HDR</source>
        <translation>HDR</translation>
    </message>
    <message>
        <source>HDR turn threshold</source>
        <translation>HDR-Wendeschwelle</translation>
    </message>
    <message>
        <source>HDR: a smaller heading change is drift, a larger one a turn</source>
        <translation>HDR: eine kleinere Kursänderung ist Drift, eine größere eine Wende</translation>
    </message>
    <message>
        <source>HDR measurement std</source>
        <translation>HDR-Messung SD</translation>
    </message>
    <message>
        <source>HDR: R of the heading measurement, std</source>
        <translation>HDR: R der Kursmessung, SD</translation>
    </message>
    <message>
        <source>Building axis from the walk</source>
        <translation>Gebäudeachse aus dem Gang</translation>
    </message>
    <message>
        <source>IPER: building axis from the walk&apos;s dominant directions</source>
        <translation>IPER: Gebäudeachse aus den Hauptrichtungen des Gangs</translation>
    </message>
    <message>
        <source>IPER</source>
        <translation>IPER</translation>
    </message>
    <message>
        <source>Building axis angle</source>
        <translation>Winkel der Gebäudeachse</translation>
    </message>
    <message>
        <source>IPER: angle of the building&apos;s main axis from x</source>
        <translation>IPER: Winkel der Hauptachse des Gebäudes gegen x</translation>
    </message>
    <message>
        <source>Along-axis tolerance</source>
        <translation>Toleranz entlang der Achse</translation>
    </message>
    <message>
        <source>IPER: walking within this of an axis counts as along it</source>
        <translation>IPER: Gehen innerhalb dieser Abweichung von einer Achse gilt als entlang der Achse</translation>
    </message>
    <message>
        <source>IPER window</source>
        <translation>IPER-Fenster</translation>
    </message>
    <message>
        <source>IPER: displacement window</source>
        <translation>IPER: Fenster der Verschiebung</translation>
    </message>
    <message>
        <source>IPER cross-axis std</source>
        <translation>IPER SD quer zur Achse</translation>
    </message>
    <message>
        <source>IPER: R of the cross-axis displacement, std</source>
        <translation>IPER: R der Verschiebung quer zur Achse, SD</translation>
    </message>
    <message>
        <source>IPER level-floor height std</source>
        <translation>IPER SD der Höhe (ebener Boden)</translation>
    </message>
    <message>
        <source>IPER: R of the level-floor height, std</source>
        <translation>IPER: R der Höhe bei ebenem Boden, SD</translation>
    </message>
    <message>
        <source>ZUNA reference period</source>
        <translation>ZUNA-Referenzdauer</translation>
    </message>
    <message>
        <source>ZUNA: static start averaged for the reference</source>
        <translation>ZUNA: ruhender Anfang, über den für die Referenz gemittelt wird</translation>
    </message>
    <message>
        <source>ZUNA</source>
        <translation>ZUNA</translation>
    </message>
    <message>
        <source>ZUNA shortest stance</source>
        <translation>ZUNA kürzeste Standphase</translation>
    </message>
    <message>
        <source>ZUNA: mid-stance needs a stance run this long</source>
        <translation>ZUNA: eine Standphasenmitte erfordert eine Standphase dieser Länge</translation>
    </message>
    <message>
        <source>ZUNA margin below the threshold</source>
        <translation>ZUNA-Abstand unter dem Schwellwert</translation>
    </message>
    <message>
        <source>ZUNA: mid-stance statistic this far below the threshold</source>
        <translation>ZUNA: Statistik in der Standphasenmitte so weit unter dem Schwellwert</translation>
    </message>
    <message>
        <source>ZUNA measurement std</source>
        <translation>ZUNA-Messung SD</translation>
    </message>
    <message>
        <source>ZUNA: R of the acceleration, std</source>
        <translation>ZUNA: R der Beschleunigung, SD</translation>
    </message>
    <message>
        <source>Pressure to height</source>
        <translation>Druck in Höhe</translation>
    </message>
    <message>
        <source>Barometric formula</source>
        <translation>Barometrische Höhenformel</translation>
    </message>
    <message>
        <source>Linear constant (Zheng et al. 2016)</source>
        <translation>Lineare Konstante (Zheng et al. 2016)</translation>
    </message>
    <message>
        <source>Barometer: pressure difference to height</source>
        <translation>Barometer: Umrechnung der Druckdifferenz in Höhe</translation>
    </message>
    <message>
        <source>Barometer</source>
        <translation>Barometer</translation>
    </message>
    <message>
        <source>Linear constant N</source>
        <translation>Lineare Konstante N</translation>
    </message>
    <message>
        <source>Barometer: linear constant N</source>
        <translation>Barometer: lineare Konstante N</translation>
    </message>
    <message>
        <source>Barometer height std</source>
        <translation>Barometerhöhe SD</translation>
    </message>
    <message>
        <source>Barometer: R of the height, std</source>
        <translation>Barometer: R der Höhe, SD</translation>
    </message>
    <message>
        <source>Level walking height change</source>
        <translation>Höhenänderung bei ebenem Gehen</translation>
    </message>
    <message>
        <source>Motion class: smaller height change per step is level walking</source>
        <translation>Bewegungsklasse: eine kleinere Höhenänderung je Schritt ist ebenes Gehen</translation>
    </message>
    <message>
        <source>Elevator pressure variance</source>
        <translation>Druckvarianz Aufzug</translation>
    </message>
    <message>
        <source>Motion class: pressure variance between steps above this is an elevator</source>
        <translation>Bewegungsklasse: eine Druckvarianz zwischen Schritten über diesem Wert ist ein Aufzug</translation>
    </message>
    <message>
        <source>Magnetometer heading std</source>
        <translation>Magnetometer-Kurs SD</translation>
    </message>
    <message>
        <source>Magnetometer: R of the heading, std</source>
        <translation>Magnetometer: R des Kurses, SD</translation>
    </message>
    <message>
        <source>Magnetometer</source>
        <translation>Magnetometer</translation>
    </message>
    <message>
        <source>Field strength tolerance</source>
        <translation>Toleranz der Feldstärke</translation>
    </message>
    <message>
        <source>Magnetometer: |m| within this fraction of its value at alignment</source>
        <translation>Magnetometer: |m| innerhalb dieses Anteils seines Werts bei der Ausrichtung</translation>
    </message>
    <message>
        <source>Dip angle tolerance</source>
        <translation>Toleranz des Inklinationswinkels</translation>
    </message>
    <message>
        <source>Magnetometer: dip within this of its value at alignment</source>
        <translation>Magnetometer: Inklination innerhalb dieser Abweichung von ihrem Wert bei der Ausrichtung</translation>
    </message>
    <message>
        <source>Q attitude</source>
        <translation>Q Lage</translation>
    </message>
    <message>
        <source>Q attitude, std per 10 ms</source>
        <translation>Q Lage, SD je 10 ms</translation>
    </message>
    <message>
        <source>Process noise</source>
        <translation>Prozessrauschen</translation>
    </message>
    <message>
        <source>Q gyroscope bias</source>
        <translation>Q Gyroskop-Bias</translation>
    </message>
    <message>
        <source>Q gyro bias, std per 10 ms</source>
        <translation>Q Gyro-Bias, SD je 10 ms</translation>
    </message>
    <message>
        <source>Q position</source>
        <translation>Q Position</translation>
    </message>
    <message>
        <source>Q position, std per 10 ms</source>
        <translation>Q Position, SD je 10 ms</translation>
    </message>
    <message>
        <source>Q velocity</source>
        <translation>Q Geschwindigkeit</translation>
    </message>
    <message>
        <source>Q velocity, std per 10 ms</source>
        <translation>Q Geschwindigkeit, SD je 10 ms</translation>
    </message>
    <message>
        <source>Q accelerometer bias</source>
        <translation>Q Beschleunigungssensor-Bias</translation>
    </message>
    <message>
        <source>Q accelerometer bias, std per 10 ms</source>
        <translation>Q Beschleunigungssensor-Bias, SD je 10 ms</translation>
    </message>
    <message>
        <source>R zero velocity</source>
        <translation>R Nullgeschwindigkeit</translation>
    </message>
    <message>
        <source>R ZUPT, std</source>
        <translation>R ZUPT, SD</translation>
    </message>
    <message>
        <source>Measurement noise</source>
        <translation>Messrauschen</translation>
    </message>
    <message>
        <source>R zero angular rate</source>
        <translation>R Null-Drehrate</translation>
    </message>
    <message>
        <source>R ZARU, std</source>
        <translation>R ZARU, SD</translation>
    </message>
    <message>
        <source>P0 attitude</source>
        <translation>P0 Lage</translation>
    </message>
    <message>
        <source>P0 attitude, std</source>
        <translation>P0 Lage, SD</translation>
    </message>
    <message>
        <source>Initial covariance</source>
        <translation>Anfangskovarianz</translation>
    </message>
    <message>
        <source>P0 gyroscope bias</source>
        <translation>P0 Gyroskop-Bias</translation>
    </message>
    <message>
        <source>P0 gyro bias, std</source>
        <translation>P0 Gyro-Bias, SD</translation>
    </message>
    <message>
        <source>P0 position</source>
        <translation>P0 Position</translation>
    </message>
    <message>
        <source>P0 position, std</source>
        <translation>P0 Position, SD</translation>
    </message>
    <message>
        <source>P0 velocity</source>
        <translation>P0 Geschwindigkeit</translation>
    </message>
    <message>
        <source>P0 velocity, std</source>
        <translation>P0 Geschwindigkeit, SD</translation>
    </message>
    <message>
        <source>P0 accelerometer bias</source>
        <translation>P0 Beschleunigungssensor-Bias</translation>
    </message>
    <message>
        <source>P0 accelerometer bias, std</source>
        <translation>P0 Beschleunigungssensor-Bias, SD</translation>
    </message>
    <message>
        <source>Innovation gate</source>
        <translation>Innovationstor</translation>
    </message>
    <message>
        <source>Aiding measurements (HDR, IPER, ZUNA, barometer, magnetometer) less likely than this under the filter&apos;s own uncertainty are rejected (chi-square test); 0: no gate. ZUPT and ZARU are never gated.</source>
        <translation>Stützmessungen (HDR, IPER, ZUNA, Barometer, Magnetometer), die unter der eigenen Unsicherheit des Filters unwahrscheinlicher sind, werden verworfen (Chi-Quadrat-Test); 0: kein Tor. ZUPT und ZARU werden nie geprüft.</translation>
    </message>
</context>
<context>
    <name>footpath::ParameterPanel</name>
    <message>
        <source>Reset to defaults</source>
        <translation>Auf Standardwerte zurücksetzen</translation>
    </message>
    <message>
        <source>Set every parameter back to its default value (one undo step)</source>
        <translation>Setzt alle Parameter auf ihre Standardwerte zurück (ein Rückgängig-Schritt)</translation>
    </message>
    <message>
        <source>Load preset...</source>
        <translation>Voreinstellung laden...</translation>
    </message>
    <message>
        <source>Save preset...</source>
        <translation>Voreinstellung speichern...</translation>
    </message>
    <message>
        <source>Back to the default (%1)</source>
        <translation>Zurück zum Standardwert (%1)</translation>
    </message>
    <message>
        <source>Reset parameters to defaults</source>
        <translation>Parameter auf Standardwerte zurücksetzen</translation>
    </message>
    <message>
        <source>%1 sets values the estimate cannot use: %2</source>
        <translation>%1 setzt Werte, die die Schätzung nicht verwenden kann: %2</translation>
    </message>
    <message>
        <source>Load preset %1</source>
        <translation>Voreinstellung %1 laden</translation>
    </message>
    <message>
        <source>Load parameter preset</source>
        <translation>Parameter-Voreinstellung laden</translation>
    </message>
    <message>
        <source>Parameter presets (*.json);;All files (*)</source>
        <translation>Parameter-Voreinstellungen (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Load preset</source>
        <translation>Voreinstellung laden</translation>
    </message>
    <message>
        <source>The preset was not loaded.

%1</source>
        <translation>Die Voreinstellung wurde nicht geladen.

%1</translation>
    </message>
    <message>
        <source>Save parameter preset</source>
        <translation>Parameter-Voreinstellung speichern</translation>
    </message>
    <message>
        <source>Parameter presets (*.json)</source>
        <translation>Parameter-Voreinstellungen (*.json)</translation>
    </message>
    <message>
        <source>Save preset</source>
        <translation>Voreinstellung speichern</translation>
    </message>
    <message>
        <source>The preset was not saved.

%1</source>
        <translation>Die Voreinstellung wurde nicht gespeichert.

%1</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Rückgängig:</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Wiederherstellen:</translation>
    </message>
    <message>
        <source>Not used: only the C1/C2/C3 detector uses it, and %1 is chosen.</source>
        <translation>Nicht verwendet: nur der C1/C2/C3-Detektor nutzt ihn, gewählt ist %1.</translation>
    </message>
    <message>
        <source>Not used: the statistic detectors (SHOE, ARED, AMVD, MBGTD) use it, and C1/C2/C3 is chosen.</source>
        <translation>Nicht verwendet: die Statistik-Detektoren (SHOE, ARED, AMVD, MBGTD) nutzen ihn, gewählt ist C1/C2/C3.</translation>
    </message>
    <message>
        <source>Not used: ARED looks at the gyroscope alone.</source>
        <translation>Nicht verwendet: ARED wertet nur das Gyroskop aus.</translation>
    </message>
    <message>
        <source>Not used: %1 looks at the accelerometer alone.</source>
        <translation>Nicht verwendet: %1 wertet nur den Beschleunigungssensor aus.</translation>
    </message>
    <message>
        <source>Not used: the threshold is adaptive (zv_adaptive is on).</source>
        <translation>Nicht verwendet: der Schwellwert ist adaptiv (zv_adaptive ist ein).</translation>
    </message>
    <message>
        <source>Not used: the threshold is fixed (zv_adaptive is off).</source>
        <translation>Nicht verwendet: der Schwellwert ist fest (zv_adaptive ist aus).</translation>
    </message>
    <message>
        <source>Not used: the 9-state filter has no bias states.</source>
        <translation>Nicht verwendet: das Filter mit 9 Zuständen hat keine Bias-Zustände.</translation>
    </message>
    <message>
        <source>Not used: ZARU corrects the gyro bias, which the 9-state filter does not estimate.</source>
        <translation>Nicht verwendet: ZARU korrigiert den Gyroskop-Bias, den das Filter mit 9 Zuständen nicht schätzt.</translation>
    </message>
    <message>
        <source>%1&lt;br&gt;Choices in presets: %2&lt;br&gt;Default: %3</source>
        <translation>%1&lt;br&gt;Auswahl in Voreinstellungen: %2&lt;br&gt;Standardwert: %3</translation>
    </message>
    <message>
        <source>Not used: HDR is off (use_hdr).</source>
        <translation>Nicht verwendet: HDR ist aus (use_hdr).</translation>
    </message>
    <message>
        <source>Not used: IPER is off (use_iper).</source>
        <translation>Nicht verwendet: IPER ist aus (use_iper).</translation>
    </message>
    <message>
        <source>Not used: the axis is estimated from the walk (iper_axis_auto is on).</source>
        <translation>Nicht verwendet: die Achse wird aus dem Gang geschätzt (iper_axis_auto ist ein).</translation>
    </message>
    <message>
        <source>Not used: ZUNA is off (use_zuna).</source>
        <translation>Nicht verwendet: ZUNA ist aus (use_zuna).</translation>
    </message>
    <message>
        <source>Not used: the barometer is off (use_baro).</source>
        <translation>Nicht verwendet: das Barometer ist aus (use_baro).</translation>
    </message>
    <message>
        <source>Not used: the barometric formula is chosen, not the linear constant.</source>
        <translation>Nicht verwendet: gewählt ist die barometrische Höhenformel, nicht die lineare Konstante.</translation>
    </message>
    <message>
        <source>Not used: the magnetometer heading update is off (use_mag_heading).</source>
        <translation>Nicht verwendet: das Magnetometer-Kursupdate ist aus (use_mag_heading).</translation>
    </message>
    <message>
        <source> (the slider up to %1; type a larger value)</source>
        <translation> (Schieberegler bis %1; größere Werte eintippen)</translation>
    </message>
    <message>
        <source>%1&lt;br&gt;Range: %2 to %3 %4%6&lt;br&gt;Default: %5 %4&lt;br&gt;Up/Down in the value field: one slider step; Page Up/Down: ten</source>
        <translation>%1&lt;br&gt;Bereich: %2 bis %3 %4%6&lt;br&gt;Standardwert: %5 %4&lt;br&gt;Auf/Ab im Wertefeld: ein Schieberegler-Schritt; Bild auf/ab: zehn</translation>
    </message>
</context>
<context>
    <name>footpath::PlotInteraction</name>
    <message>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <source>   Δt = %1 s from the marker</source>
        <translation>   Δt = %1 s von der Markierung</translation>
    </message>
    <message>
        <source> (Δ %1)</source>
        <translation> (Δ %1)</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>Could not write %1.</source>
        <translation>%1 konnte nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>Reset view</source>
        <translation>Ansicht zurücksetzen</translation>
    </message>
    <message>
        <source>Clear measurement marker</source>
        <translation>Messmarkierung entfernen</translation>
    </message>
    <message>
        <source>Shift+click sets the marker; the readout then shows the differences to it</source>
        <translation>Umschalt+Klick setzt die Markierung; die Anzeige zeigt dann die Differenzen zu ihr</translation>
    </message>
    <message>
        <source>Export as PNG…</source>
        <translation>Als PNG exportieren…</translation>
    </message>
    <message>
        <source>Export plot as PNG</source>
        <translation>Diagramm als PNG exportieren</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG-Bilder (*.png)</translation>
    </message>
    <message>
        <source>Export as SVG…</source>
        <translation>Als SVG exportieren…</translation>
    </message>
    <message>
        <source>Export plot as SVG</source>
        <translation>Diagramm als SVG exportieren</translation>
    </message>
    <message>
        <source>SVG images (*.svg)</source>
        <translation>SVG-Bilder (*.svg)</translation>
    </message>
    <message>
        <source>Export as PDF (vector)…</source>
        <translation>Als PDF exportieren (Vektor)…</translation>
    </message>
    <message>
        <source>Export plot as PDF</source>
        <translation>Diagramm als PDF exportieren</translation>
    </message>
    <message>
        <source>PDF documents (*.pdf)</source>
        <translation>PDF-Dokumente (*.pdf)</translation>
    </message>
    <message>
        <source>Export visible data as CSV…</source>
        <translation>Sichtbare Daten als CSV exportieren…</translation>
    </message>
    <message>
        <source>Export visible data as CSV</source>
        <translation>Sichtbare Daten als CSV exportieren</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
</context>
<context>
    <name>footpath::ReconnectOffer</name>
    <message>
        <source>Reconnect</source>
        <translation>Neu verbinden</translation>
    </message>
    <message>
        <source>Dismiss</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <source>&lt;b&gt;The device went away:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Das Gerät ist verschwunden:&lt;/b&gt; %1</translation>
    </message>
    <message>
        <source>Reconnecting continues the recording in %1.</source>
        <translation>Beim erneuten Verbinden wird die Aufzeichnung in %1 fortgesetzt.</translation>
    </message>
    <message>
        <source>%1 is back: reconnect?</source>
        <translation>%1 ist wieder da: neu verbinden?</translation>
    </message>
    <message>
        <source>Waiting for %1 to come back (plug the sensor in again)...</source>
        <translation>Warte, bis %1 wieder da ist (Sensor erneut anstecken)...</translation>
    </message>
</context>
<context>
    <name>footpath::RecordedInputPanel</name>
    <message>
        <source>Open recording...</source>
        <translation>Aufzeichnung öffnen...</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Recent</source>
        <translation>Zuletzt</translation>
    </message>
    <message>
        <source>Open a recording: Xsens text export or .mtb log, pyshoe CSV, or any delimited text with time, acceleration and angular rate. You can also drop a file here.</source>
        <translation>Öffnen Sie eine Aufzeichnung: Xsens-Textexport oder .mtb-Log, pyshoe-CSV oder beliebigen Text mit Trennzeichen, der Zeit, Beschleunigung und Drehrate enthält. Sie können eine Datei auch hierher ziehen.</translation>
    </message>
    <message>
        <source>Reading %1: %p%</source>
        <translation>%1 wird gelesen: %p%</translation>
    </message>
    <message>
        <source>Format</source>
        <translation>Format</translation>
    </message>
    <message>
        <source>Samples</source>
        <translation>Abtastwerte</translation>
    </message>
    <message>
        <source>Rate</source>
        <translation>Rate</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message>
        <source>Duration</source>
        <translation>Dauer</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>Channels</source>
        <translation>Kanäle</translation>
    </message>
    <message>
        <source>Units in file</source>
        <translation>Dateieinheiten</translation>
    </message>
    <message>
        <source>Gaps</source>
        <translation>Lücken</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>%1 (about %2 samples lost), longest %3 s</source>
        <translation>%1 (etwa %2 Abtastwerte verloren), längste %3 s</translation>
    </message>
    <message>
        <source>Warning:</source>
        <translation>Warnung:</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;Left foot&lt;/b&gt;&lt;/p&gt;%1&lt;hr&gt;&lt;p&gt;&lt;b&gt;Right foot&lt;/b&gt;&lt;/p&gt;%2</source>
        <translation>&lt;p&gt;&lt;b&gt;Linker Fuß&lt;/b&gt;&lt;/p&gt;%1&lt;hr&gt;&lt;p&gt;&lt;b&gt;Rechter Fuß&lt;/b&gt;&lt;/p&gt;%2</translation>
    </message>
</context>
<context>
    <name>footpath::RunHistory</name>
    <message>
        <source>First run</source>
        <translation>Erster Lauf</translation>
    </message>
    <message>
        <source>on</source>
        <translation>ein</translation>
    </message>
    <message>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message numerus="yes">
        <source>%1; %2 and %n more</source>
        <translation>
            <numerusform>%1; %2 und %n weiterer</numerusform>
            <numerusform>%1; %2 und %n weitere</numerusform>
        </translation>
    </message>
    <message>
        <source>No change</source>
        <translation>Keine Änderung</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Lauf</translation>
    </message>
    <message>
        <source>Change</source>
        <translation>Änderung</translation>
    </message>
    <message>
        <source>Path (m)</source>
        <translation>Weg (m)</translation>
    </message>
    <message>
        <source>End to start (m)</source>
        <translation>Ende bis Start (m)</translation>
    </message>
    <message>
        <source>ARMSE 2D (m)</source>
        <translation>ARMSE 2D (m)</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>Schritte</translation>
    </message>
    <message>
        <source>Back to run %1: %2</source>
        <translation>Zurück zu Lauf %1: %2</translation>
    </message>
</context>
<context>
    <name>footpath::RunHistoryPanel</name>
    <message>
        <source>Go back to this run</source>
        <translation>Zu diesem Lauf zurückkehren</translation>
    </message>
    <message>
        <source>The last %1 estimates of this recording (bold: the one shown). Double-click one to go back to its parameters; Undo goes back too.</source>
        <translation>Die letzten %1 Schätzungen dieser Aufzeichnung (fett: die angezeigte). Doppelklick auf eine kehrt zu ihren Parametern zurück; Rückgängig geht ebenfalls zurück.</translation>
    </message>
</context>
<context>
    <name>footpath::SignalPlots</name>
    <message>
        <source>x</source>
        <translation>x</translation>
    </message>
    <message>
        <source>y</source>
        <translation>y</translation>
    </message>
    <message>
        <source>z</source>
        <translation>z</translation>
    </message>
    <message>
        <source>|a|</source>
        <translation>|a|</translation>
    </message>
    <message>
        <source>Pressure</source>
        <translation>Druck</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Höhe</translation>
    </message>
    <message>
        <source>Acceleration</source>
        <translation>Beschleunigung</translation>
    </message>
    <message>
        <source>Acceleration
(m/s²)</source>
        <translation>Beschleunigung
(m/s²)</translation>
    </message>
    <message>
        <source>Angular rate</source>
        <translation>Drehrate</translation>
    </message>
    <message>
        <source>Angular rate
(rad/s)</source>
        <translation>Drehrate
(rad/s)</translation>
    </message>
    <message>
        <source>Magnetic field</source>
        <translation>Magnetfeld</translation>
    </message>
    <message>
        <source>Magnetic field
(file units)</source>
        <translation>Magnetfeld
(Dateieinheit)</translation>
    </message>
    <message>
        <source>Pressure
(hPa)</source>
        <translation>Druck
(hPa)</translation>
    </message>
    <message>
        <source>Baro. height
(m)</source>
        <translation>Baro. Höhe
(m)</translation>
    </message>
    <message>
        <source>Channels</source>
        <translation>Kanäle</translation>
    </message>
    <message>
        <source>Stance</source>
        <translation>Standphase</translation>
    </message>
    <message>
        <source>Show or hide this channel of the %1 row</source>
        <translation>Diesen Kanal der Zeile „%1“ ein- oder ausblenden</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>Heel strike</source>
        <translation>Fersenaufsatz</translation>
    </message>
    <message>
        <source>Toe off</source>
        <translation>Zehenablösung</translation>
    </message>
</context>
<context>
    <name>footpath::StanceFlagsPlot</name>
    <message>
        <source>C1: |a| in range</source>
        <translation>C1: |a| im Bereich</translation>
    </message>
    <message>
        <source>C2: |a| steady</source>
        <translation>C2: |a| ruhig</translation>
    </message>
    <message>
        <source>C3: |ω| small</source>
        <translation>C3: |ω| klein</translation>
    </message>
    <message>
        <source>C = C1·C2·C3</source>
        <translation>C = C1·C2·C3</translation>
    </message>
    <message>
        <source>Stance (median)</source>
        <translation>Standphase (Median)</translation>
    </message>
    <message>
        <source>|a|</source>
        <translation>|a|</translation>
    </message>
    <message>
        <source>|a|
(m/s²)</source>
        <translation>|a|
(m/s²)</translation>
    </message>
    <message>
        <source>std of |a|</source>
        <translation>SD von |a|</translation>
    </message>
    <message>
        <source>std of |a|
(m/s²)</source>
        <translation>SD |a|
(m/s²)</translation>
    </message>
    <message>
        <source>|ω|</source>
        <translation>|ω|</translation>
    </message>
    <message>
        <source>|ω|
(rad/s)</source>
        <translation>|ω|
(rad/s)</translation>
    </message>
    <message>
        <source>min |a| = %1 m/s²</source>
        <translation>min |a| = %1 m/s²</translation>
    </message>
    <message>
        <source>max |a| = %1 m/s²</source>
        <translation>max |a| = %1 m/s²</translation>
    </message>
    <message>
        <source>max std = %1 m/s²</source>
        <translation>max SD = %1 m/s²</translation>
    </message>
    <message>
        <source>max |ω| = %1 rad/s</source>
        <translation>max |ω| = %1 rad/s</translation>
    </message>
    <message>
        <source>Detector</source>
        <translation>Detektor</translation>
    </message>
    <message>
        <source>Show detector inputs</source>
        <translation>Detektoreingänge zeigen</translation>
    </message>
    <message>
        <source>Plot |a|, its local standard deviation and |ω| with the detector&apos;s thresholds</source>
        <translation>|a|, seine lokale Standardabweichung und |ω| mit den Schwellwerten des Detektors darstellen</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>C: statistic
&lt; threshold</source>
        <translation>C: Statistik
&lt; Schwellwert</translation>
    </message>
    <message>
        <source>Stance</source>
        <translation>Standphase</translation>
    </message>
    <message>
        <source>The inputs of the C1/C2/C3 detector; the chosen detector decides on its statistic, shown below the lanes</source>
        <translation>Die Eingänge des C1/C2/C3-Detektors; der gewählte Detektor entscheidet anhand seiner Statistik, die unter den Spuren dargestellt ist</translation>
    </message>
    <message>
        <source>threshold (adaptive)</source>
        <translation>Schwellwert (adaptiv)</translation>
    </message>
    <message>
        <source>threshold = 10^%1</source>
        <translation>Schwellwert = 10^%1</translation>
    </message>
    <message>
        <source>stance</source>
        <translation>Standphase</translation>
    </message>
    <message>
        <source>swing</source>
        <translation>Schwungphase</translation>
    </message>
    <message>
        <source>1 (set)</source>
        <translation>1 (gesetzt)</translation>
    </message>
    <message>
        <source>0</source>
        <translation>0</translation>
    </message>
    <message>
        <source>Reference
stance</source>
        <translation>Referenz-
Standphase</translation>
    </message>
    <message>
        <source>Reference stance</source>
        <translation>Referenz-Standphase</translation>
    </message>
    <message>
        <source>from the recording&apos;s reference stance column (zero velocity by motion capture)</source>
        <translation>aus der Referenz-Standphasenspalte der Aufzeichnung (Nullgeschwindigkeit per Motion Capture)</translation>
    </message>
    <message>
        <source>between the hand-labelled gait events (toe-off, heel-strike)</source>
        <translation>zwischen den von Hand markierten Gangereignissen (Zehenablösung, Fersenaufsatz)</translation>
    </message>
    <message>
        <source>%1
statistic</source>
        <translation>%1-
Statistik</translation>
    </message>
</context>
<context>
    <name>footpath::StatePlots</name>
    <message>
        <source>Attitude
(°)</source>
        <translation>Lage
(°)</translation>
    </message>
    <message>
        <source>roll</source>
        <translation>Rollen</translation>
    </message>
    <message>
        <source>pitch</source>
        <translation>Nicken</translation>
    </message>
    <message>
        <source>yaw</source>
        <translation>Gieren</translation>
    </message>
    <message>
        <source>Velocity
(m/s)</source>
        <translation>Geschwindigkeit
(m/s)</translation>
    </message>
    <message>
        <source>x</source>
        <translation>x</translation>
    </message>
    <message>
        <source>y</source>
        <translation>y</translation>
    </message>
    <message>
        <source>z</source>
        <translation>z</translation>
    </message>
    <message>
        <source>Height
(m)</source>
        <translation>Höhe
(m)</translation>
    </message>
    <message>
        <source>height</source>
        <translation>Höhe</translation>
    </message>
    <message>
        <source>Gyro bias
(rad/s)</source>
        <translation>Gyro-Bias
(rad/s)</translation>
    </message>
    <message>
        <source>Acc. bias
(m/s²)</source>
        <translation>Beschl.-Bias
(m/s²)</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>±1σ</source>
        <translation>±1σ</translation>
    </message>
    <message>
        <source>σ %1</source>
        <translation>σ %1</translation>
    </message>
    <message>
        <source>Not estimated (constant)</source>
        <translation>Nicht geschätzt (konstant)</translation>
    </message>
    <message>
        <source>No ±1σ band: this estimator keeps no covariance</source>
        <translation>Kein ±1σ-Band: dieser Schätzer führt keine Kovarianz</translation>
    </message>
</context>
<context>
    <name>footpath::SummaryPanel</name>
    <message>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <source>Start (s)</source>
        <translation>Beginn (s)</translation>
    </message>
    <message>
        <source>End (s)</source>
        <translation>Ende (s)</translation>
    </message>
    <message>
        <source>Stance (s)</source>
        <translation>Standphase (s)</translation>
    </message>
    <message>
        <source>Stride (m)</source>
        <translation>Doppelschritt (m)</translation>
    </message>
    <message>
        <source>Stride time (s)</source>
        <translation>Doppelschritt (s)</translation>
    </message>
    <message>
        <source>x (m)</source>
        <translation>x (m)</translation>
    </message>
    <message>
        <source>y (m)</source>
        <translation>y (m)</translation>
    </message>
    <message>
        <source>z (m)</source>
        <translation>z (m)</translation>
    </message>
    <message>
        <source>When the foot came to rest</source>
        <translation>Zeitpunkt, zu dem der Fuß zur Ruhe kam</translation>
    </message>
    <message>
        <source>When the foot lifted off</source>
        <translation>Zeitpunkt, zu dem der Fuß abhob</translation>
    </message>
    <message>
        <source>How long the foot was at rest</source>
        <translation>Wie lange der Fuß ruhte</translation>
    </message>
    <message>
        <source>Horizontal distance from the previous stance</source>
        <translation>Horizontaler Abstand zur vorigen Standphase</translation>
    </message>
    <message>
        <source>Time from the previous stance start to this one</source>
        <translation>Zeit vom Beginn der vorigen Standphase bis zum Beginn dieser</translation>
    </message>
    <message>
        <source>Mean position during the stance, relative to the start</source>
        <translation>Mittlere Position während der Standphase, relativ zum Start</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>Schritte</translation>
    </message>
    <message>
        <source>Per step</source>
        <translation>Je Schritt</translation>
    </message>
    <message>
        <source>Distributions</source>
        <translation>Verteilungen</translation>
    </message>
    <message>
        <source>Walk</source>
        <translation>Gang</translation>
    </message>
    <message>
        <source>Path length</source>
        <translation>Weglänge</translation>
    </message>
    <message>
        <source>Stance phases / strides</source>
        <translation>Standphasen / Doppelschritte</translation>
    </message>
    <message>
        <source>Duration</source>
        <translation>Dauer</translation>
    </message>
    <message>
        <source>Cadence</source>
        <translation>Schrittfrequenz</translation>
    </message>
    <message>
        <source>Stride length</source>
        <translation>Doppelschrittlänge</translation>
    </message>
    <message>
        <source>Stride duration</source>
        <translation>Doppelschrittdauer</translation>
    </message>
    <message>
        <source>Stance duration</source>
        <translation>Standphasendauer</translation>
    </message>
    <message>
        <source>End to start</source>
        <translation>Ende–Start</translation>
    </message>
    <message>
        <source>Against the reference</source>
        <translation>Gegenüber der Referenz</translation>
    </message>
    <message>
        <source>ARMSE 2D</source>
        <translation>ARMSE 2D</translation>
    </message>
    <message>
        <source>ARMSE 3D</source>
        <translation>ARMSE 3D</translation>
    </message>
    <message>
        <source>Loop closure</source>
        <translation>Schleifenschluss</translation>
    </message>
    <message>
        <source>Distance error</source>
        <translation>Streckenfehler</translation>
    </message>
    <message>
        <source>000 steps/min (00.0 strides/min)</source>
        <translation>000/min (00.0 Doppelschritte/min)</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>%1 / %2</source>
        <translation>%1 / %2</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>%1 steps/min (%2 strides/min)</source>
        <translation>%1/min (%2 Doppelschritte/min)</translation>
    </message>
    <message>
        <source>%1 ± %2 m</source>
        <translation>%1 ± %2 m</translation>
    </message>
    <message>
        <source>%1 s (median %2 s)</source>
        <translation>%1 s (Median %2 s)</translation>
    </message>
    <message>
        <source>%1 m (%2 % of the path)</source>
        <translation>%1 m (%2 % des Wegs)</translation>
    </message>
    <message>
        <source>%1 m (%2 % of %3 m)</source>
        <translation>%1 m (%2 % von %3 m)</translation>
    </message>
    <message>
        <source>Stride length per step</source>
        <translation>Doppelschrittlänge je Schritt</translation>
    </message>
    <message>
        <source>Stride length (m)</source>
        <translation>Doppelschrittlänge (m)</translation>
    </message>
    <message>
        <source>Stance duration per step</source>
        <translation>Standphasendauer je Schritt</translation>
    </message>
    <message>
        <source>Stance duration (s)</source>
        <translation>Standphasendauer (s)</translation>
    </message>
    <message>
        <source>Grey bars: %1 values below and %2 above the regular bins (outliers such as the standing still at the start and end)</source>
        <translation>Graue Balken: %1 Werte unterhalb und %2 oberhalb der regulären Klassen (Ausreißer wie das Stillstehen am Anfang und Ende)</translation>
    </message>
    <message>
        <source>Count</source>
        <translation>Anzahl</translation>
    </message>
    <message>
        <source>No plausibility warnings</source>
        <translation>Keine Plausibilitätswarnungen</translation>
    </message>
    <message numerus="yes">
        <source>%n plausibility warning(s)</source>
        <translation>
            <numerusform>%n Plausibilitätswarnung</numerusform>
            <numerusform>%n Plausibilitätswarnungen</numerusform>
        </translation>
    </message>
    <message>
        <source>Click the time span to move the time cursor there</source>
        <translation>Auf den Zeitraum klicken, um den Zeitcursor dorthin zu setzen</translation>
    </message>
    <message>
        <source>Heel strike (s)</source>
        <translation>Fersenaufsatz (s)</translation>
    </message>
    <message>
        <source>Toe off (s)</source>
        <translation>Zehenablösung (s)</translation>
    </message>
    <message>
        <source>Gait stance (%)</source>
        <translation>Gang-Standphase (%)</translation>
    </message>
    <message>
        <source>Clearance (m)</source>
        <translation>Fußfreiheit (m)</translation>
    </message>
    <message>
        <source>The gait stride whose stance holds this step: when the foot landed</source>
        <translation>Der Gang-Doppelschritt, dessen Standphase diesen Schritt enthält: wann der Fuß aufsetzte</translation>
    </message>
    <message>
        <source>When the foot left the ground (the end of the gait lab&apos;s stance)</source>
        <translation>Wann der Fuß den Boden verließ (das Ende der Standphase im Ganglabor-Sinn)</translation>
    </message>
    <message>
        <source>Heel strike to toe off, % of the stride time</source>
        <translation>Fersenaufsatz bis Zehenablösung, % der Doppelschrittdauer</translation>
    </message>
    <message>
        <source>Highest point of the swing after this stance above it</source>
        <translation>Höchster Punkt der Schwungphase nach dieser Standphase, über ihr</translation>
    </message>
    <message>
        <source>Gait</source>
        <translation>Gang</translation>
    </message>
    <message>
        <source>Gait (heel strike to toe off)</source>
        <translation>Gang (Fersenaufsatz bis Zehenablösung)</translation>
    </message>
    <message>
        <source>Strides</source>
        <translation>Doppelschritte</translation>
    </message>
    <message>
        <source>Stride time</source>
        <translation>Doppelschrittdauer</translation>
    </message>
    <message>
        <source>Stance / swing</source>
        <translation>Standphase / Schwungphase</translation>
    </message>
    <message>
        <source>Foot clearance</source>
        <translation>Fußfreiheit</translation>
    </message>
    <message>
        <source>From the gait events (heel strike, toe off) of this foot: means over the strides that neither turn nor pause</source>
        <translation>Aus den Gangereignissen (Fersenaufsatz, Zehenablösung) dieses Fußes: Mittelwerte über die Doppelschritte, die weder wenden noch pausieren</translation>
    </message>
    <message>
        <source>Both feet</source>
        <translation>Beide Füße</translation>
    </message>
    <message>
        <source>Double support</source>
        <translation>Doppelstandphase</translation>
    </message>
    <message>
        <source>Stance left / right</source>
        <translation>Standphase links / rechts</translation>
    </message>
    <message>
        <source>Symmetry: stride time</source>
        <translation>Symmetrie: Doppelschrittdauer</translation>
    </message>
    <message>
        <source>Symmetry: stride length</source>
        <translation>Symmetrie: Doppelschrittlänge</translation>
    </message>
    <message>
        <source>Symmetry: stance</source>
        <translation>Symmetrie: Standphase</translation>
    </message>
    <message>
        <source>Symmetry: swing</source>
        <translation>Symmetrie: Schwungphase</translation>
    </message>
    <message>
        <source>Double support: the share of the gait cycle both feet are on the ground. Symmetry index: 100 (left - right) / mean, 0 symmetric, positive: the left larger.</source>
        <translation>Doppelstandphase: der Anteil des Gangzyklus, in dem beide Füße am Boden sind. Symmetrieindex: 100 (links - rechts) / Mittelwert, 0 symmetrisch, positiv: links größer.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Live session&lt;/b&gt;: the figures of the estimate so far. The recorded walk&apos;s return when its views are shown again.</source>
        <translation>&lt;b&gt;Live-Sitzung&lt;/b&gt;: die Kennzahlen der bisherigen Schätzung. Die des aufgezeichneten Gangs kehren zurück, wenn seine Ansichten wieder gezeigt werden.</translation>
    </message>
    <message>
        <source>Last change</source>
        <translation>Letzte Änderung</translation>
    </message>
    <message>
        <source>The figures before and after the last parameter change (the grey ghost path). Green: better, red: worse. The History lists every run.</source>
        <translation>Die Kennzahlen vor und nach der letzten Parameteränderung (der graue Geisterweg). Grün: besser, rot: schlechter. Der Verlauf listet jeden Lauf.</translation>
    </message>
    <message>
        <source>%1 → %2 m</source>
        <translation>%1 → %2 m</translation>
    </message>
    <message>
        <source>%1 → %2</source>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <source>%1 (%2 turning)</source>
        <translation>%1 (%2 wendend)</translation>
    </message>
    <message>
        <source>%1 steps/min</source>
        <translation>%1 Schritte/min</translation>
    </message>
    <message>
        <source>%1 % / %2 %</source>
        <translation>%1 % / %2 %</translation>
    </message>
    <message>
        <source>%1 % of the gait cycle (%2 strides)</source>
        <translation>%1 % des Gangzyklus (%2 Doppelschritte)</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>Gait stance per stride (heel strike to toe off)</source>
        <translation>Gang-Standphase je Doppelschritt (Fersenaufsatz bis Zehenablösung)</translation>
    </message>
    <message>
        <source>Stance (% of the stride)</source>
        <translation>Standphase (% des Doppelschritts)</translation>
    </message>
    <message>
        <source>Stride</source>
        <translation>Doppelschritt</translation>
    </message>
    <message>
        <source>Foot clearance per stride</source>
        <translation>Fußfreiheit je Doppelschritt</translation>
    </message>
    <message>
        <source>Gait stance P / R / F1</source>
        <translation>Gang-Standphase P / R / F1</translation>
    </message>
    <message>
        <source>Strides in the trial</source>
        <translation>Doppelschritte im Versuch</translation>
    </message>
    <message>
        <source>At rest (ZUPT) precision</source>
        <translation>In Ruhe (ZUPT): Präzision</translation>
    </message>
    <message>
        <source>At rest (ZUPT) recall</source>
        <translation>In Ruhe (ZUPT): Trefferquote</translation>
    </message>
    <message>
        <source>At rest (ZUPT) F1</source>
        <translation>In Ruhe (ZUPT): F1</translation>
    </message>
    <message>
        <source>The gait events&apos; stance (heel strike to toe off) against the labelled one, sample by sample: precision, recall and F1. This is the figure to compare with a gait lab&apos;s labels.</source>
        <translation>Die Standphase der Gangereignisse (Fersenaufsatz bis Zehenablösung) gegenüber der markierten, Abtastwert für Abtastwert: Präzision, Trefferquote und F1. Dies ist die Kennzahl für den Vergleich mit den Markierungen eines Ganglabors.</translation>
    </message>
    <message>
        <source>The detector&apos;s foot at rest (the zero-velocity updates) against the labelled stance. The foot rests only in the middle of its stance, so the recall is low by design; the precision says no swing was taken for rest.</source>
        <translation>Der vom Detektor als ruhend erkannte Fuß (die Nullgeschwindigkeits-Updates) gegenüber der markierten Standphase. Der Fuß ruht nur in der Mitte seiner Standphase, daher ist die Trefferquote konstruktionsbedingt niedrig; die Präzision zeigt, dass keine Schwungphase als Ruhe gewertet wurde.</translation>
    </message>
    <message>
        <source>Strides whose swing lies inside the labelled trial, against the labelled swings there</source>
        <translation>Doppelschritte, deren Schwungphase im markierten Versuch liegt, gegenüber den dort markierten Schwungphasen</translation>
    </message>
    <message>
        <source>Movements between stances that were no stride (under %1 m, or never turning at a swing&apos;s %2 rad/s: shifting the weight while standing), merged into one stance:</source>
        <translation>Bewegungen zwischen Standphasen, die kein Doppelschritt waren (unter %1 m oder nie mit den %2 rad/s einer Schwungphase drehend: Gewichtsverlagerung im Stehen), zu einer Standphase zusammengelegt:</translation>
    </message>
    <message>
        <source>%1-%2 s: %3 m, at most %4 rad/s</source>
        <translation>%1-%2 s: %3 m, höchstens %4 rad/s</translation>
    </message>
    <message>
        <source>... and %1 more</source>
        <translation>... und %1 weitere</translation>
    </message>
    <message>
        <source>%1 / %2 (%3 merged: no swing)</source>
        <translation>%1 / %2 (%3 zusammengelegt: keine Schwungphase)</translation>
    </message>
    <message>
        <source>%1 detected, %2 labelled swings</source>
        <translation>%1 erkannt, %2 markierte Schwungphasen</translation>
    </message>
    <message>
        <source>%1 / %2 / %3</source>
        <translation>%1 / %2 / %3</translation>
    </message>
</context>
<context>
    <name>footpath::TrajectoryView2D</name>
    <message>
        <source>Reference</source>
        <translation>Referenz</translation>
    </message>
    <message>
        <source>Foot path</source>
        <translation>Fußtrajektorie</translation>
    </message>
    <message>
        <source>Stance</source>
        <translation>Standphase</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>End</source>
        <translation>Ende</translation>
    </message>
    <message>
        <source>Time cursor</source>
        <translation>Zeitmarke</translation>
    </message>
    <message>
        <source>x (m)</source>
        <translation>x (m)</translation>
    </message>
    <message>
        <source>y (m)</source>
        <translation>y (m)</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>foot speed (m/s)</source>
        <translation>Fußgeschwindigkeit (m/s)</translation>
    </message>
    <message>
        <source>x = %1 m   y = %2 m   t = %3 s</source>
        <translation>x = %1 m   y = %2 m   t = %3 s</translation>
    </message>
    <message>
        <source>
from the marker: Δt = %1 s   Δx = %2 m   Δy = %3 m   distance %4 m</source>
        <translation>
von der Markierung: Δt = %1 s   Δx = %2 m   Δy = %3 m   Abstand %4 m</translation>
    </message>
    <message>
        <source>Before the last change</source>
        <translation>Vor der letzten Änderung</translation>
    </message>
</context>
<context>
    <name>footpath::TrajectoryView3D</name>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>Vertical exaggeration: heights are drawn this many times larger</source>
        <translation>Vertikale Überhöhung: Höhen werden um diesen Faktor vergrößert gezeichnet</translation>
    </message>
    <message>
        <source>Height ×</source>
        <translation>Höhe ×</translation>
    </message>
    <message>
        <source>Perspective</source>
        <translation>Perspektive</translation>
    </message>
    <message>
        <source>Reset view</source>
        <translation>Ansicht zurücksetzen</translation>
    </message>
    <message>
        <source>Oblique view of the whole path (or double-click the view)</source>
        <translation>Schrägansicht des ganzen Wegs (oder Doppelklick in die Ansicht)</translation>
    </message>
    <message>
        <source>No trajectory</source>
        <translation>Keine Trajektorie</translation>
    </message>
    <message>
        <source>x</source>
        <translation>x</translation>
    </message>
    <message>
        <source>y</source>
        <translation>y</translation>
    </message>
    <message>
        <source>z</source>
        <translation>z</translation>
    </message>
    <message>
        <source>Foot path</source>
        <translation>Fußtrajektorie</translation>
    </message>
    <message>
        <source>Shadow on the floor</source>
        <translation>Bodenschatten</translation>
    </message>
    <message>
        <source>Reference</source>
        <translation>Referenz</translation>
    </message>
    <message>
        <source>Stance</source>
        <translation>Standphase</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>End</source>
        <translation>Ende</translation>
    </message>
    <message>
        <source>Time cursor</source>
        <translation>Zeitmarke</translation>
    </message>
    <message>
        <source>Heights drawn × %1</source>
        <translation>Höhen × %1 gezeichnet</translation>
    </message>
    <message>
        <source>Before the last change</source>
        <translation>Vor der letzten Änderung</translation>
    </message>
</context>
<context>
    <name>footpath::TuneCriterionChoice</name>
    <message>
        <source>Minimise</source>
        <translation>Minimieren</translation>
    </message>
</context>
<context>
    <name>footpath::TuneDialog</name>
    <message>
        <source>on</source>
        <translation>ein</translation>
    </message>
    <message>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <source>End-to-start distance of a closed walk (%)</source>
        <translation>Abstand Ende–Start eines geschlossenen Gangs (%)</translation>
    </message>
    <message>
        <source>Error of the path length (%)</source>
        <translation>Fehler der Weglänge (%)</translation>
    </message>
    <message>
        <source>Position error against the reference (ARMSE, m)</source>
        <translation>Positionsfehler gegenüber der Referenz (ARMSE, m)</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>The criterion the search minimised</source>
        <translation>Das Kriterium, das die Suche minimiert hat</translation>
    </message>
    <message>
        <source>Tune for %1</source>
        <translation>Optimieren für %1</translation>
    </message>
    <message>
        <source>What is known about the walk</source>
        <translation>Was über den Gang bekannt ist</translation>
    </message>
    <message>
        <source>The walk ends where it started</source>
        <translation>Der Gang endet, wo er begann</translation>
    </message>
    <message>
        <source>Then the distance from its end to its start is the error to minimise</source>
        <translation>Dann ist der Abstand von seinem Ende zu seinem Start der zu minimierende Fehler</translation>
    </message>
    <message>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>The length of the walked path, if measured; then the error of the estimated length is the error to minimise</source>
        <translation>Die Länge des gegangenen Wegs, falls gemessen; dann ist der Fehler der geschätzten Länge der zu minimierende Fehler</translation>
    </message>
    <message>
        <source>Path length:</source>
        <translation>Weglänge:</translation>
    </message>
    <message>
        <source>Parameter sets to try, the current one included; more finds better settings but takes longer</source>
        <translation>Zu probierende Parametersätze, einschließlich des aktuellen; mehr findet bessere Einstellungen, dauert aber länger</translation>
    </message>
    <message numerus="yes">
        <source>on %n core(s)</source>
        <translation>
            <numerusform>auf %n Kern</numerusform>
            <numerusform>auf %n Kernen</numerusform>
        </translation>
    </message>
    <message>
        <source>Evaluations:</source>
        <translation>Auswertungen:</translation>
    </message>
    <message>
        <source>%v of %m evaluations</source>
        <translation>%v von %m Auswertungen</translation>
    </message>
    <message>
        <source>What changed</source>
        <translation>Was sich geändert hat</translation>
    </message>
    <message>
        <source>Before</source>
        <translation>Vorher</translation>
    </message>
    <message>
        <source>After</source>
        <translation>Nachher</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>Stop searching and keep the best parameters found so far</source>
        <translation>Die Suche beenden und die bisher besten Parameter behalten</translation>
    </message>
    <message>
        <source>Use the tuned parameters</source>
        <translation>Die optimierten Parameter verwenden</translation>
    </message>
    <message>
        <source>Make them the workspace&apos;s parameters (Edit &gt; Undo brings the current ones back)</source>
        <translation>Sie zu den Parametern des Arbeitsbereichs machen (Bearbeiten &gt; Rückgängig holt die aktuellen zurück)</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <source>no recording is open</source>
        <translation>keine Aufzeichnung ist geöffnet</translation>
    </message>
    <message>
        <source>needs a walk that ends where it started: tick it if yours does</source>
        <translation>benötigt einen Gang, der endet, wo er begann: ankreuzen, wenn Ihrer das tut</translation>
    </message>
    <message>
        <source>needs the path length: enter it</source>
        <translation>benötigt die Weglänge: geben Sie sie ein</translation>
    </message>
    <message>
        <source>needs reference positions: this recording has none</source>
        <translation>benötigt Referenzpositionen: diese Aufzeichnung hat keine</translation>
    </message>
    <message>
        <source>Trying the current parameters, then a spread over the whole range...</source>
        <translation>Probiere die aktuellen Parameter, dann eine Streuung über den ganzen Bereich...</translation>
    </message>
    <message>
        <source>Stopping; the best parameters so far are kept...</source>
        <translation>Wird beendet; die bisher besten Parameter werden behalten...</translation>
    </message>
    <message>
        <source>Best so far: %1</source>
        <translation>Bisher am besten: %1</translation>
    </message>
    <message>
        <source>Searching around the best parameters found so far...</source>
        <translation>Suche um die bisher besten Parameter...</translation>
    </message>
    <message>
        <source>Best: %1</source>
        <translation>Am besten: %1</translation>
    </message>
    <message numerus="yes">
        <source>Stopped after %n evaluation(s).</source>
        <translation>
            <numerusform>Angehalten nach %n Auswertung.</numerusform>
            <numerusform>Angehalten nach %n Auswertungen.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Done: %n evaluation(s).</source>
        <translation>
            <numerusform>Fertig: %n Auswertung.</numerusform>
            <numerusform>Fertig: %n Auswertungen.</numerusform>
        </translation>
    </message>
    <message>
        <source>No better parameters were found; the current ones stay.</source>
        <translation>Es wurden keine besseren Parameter gefunden; die aktuellen bleiben.</translation>
    </message>
    <message>
        <source>The path with the tuned parameters, over the current one (orange). Use them, or keep the current ones.</source>
        <translation>Der Weg mit den optimierten Parametern, über dem aktuellen (orange). Verwenden Sie sie oder behalten Sie die aktuellen.</translation>
    </message>
    <message>
        <source>Path length</source>
        <translation>Weglänge</translation>
    </message>
    <message>
        <source>The estimated path&apos;s length, for comparison</source>
        <translation>Die Länge des geschätzten Wegs, zum Vergleich</translation>
    </message>
    <message>
        <source>End to start</source>
        <translation>Ende bis Start</translation>
    </message>
    <message>
        <source>The distance from the path&apos;s end to its start, for comparison</source>
        <translation>Der Abstand vom Ende des Wegs zu seinem Start, zum Vergleich</translation>
    </message>
    <message>
        <source>Beware: the tuned path is %1 % shorter than the current one; a smaller error may come from a path that shrank rather than from a better one.</source>
        <translation>Achtung: der optimierte Weg ist %1 % kürzer als der aktuelle; ein kleinerer Fehler kann von einem geschrumpften statt von einem besseren Weg kommen.</translation>
    </message>
    <message>
        <source>Beware: the tuned path is %1 % longer than the current one.</source>
        <translation>Achtung: der optimierte Weg ist %1 % länger als der aktuelle.</translation>
    </message>
    <message>
        <source>Current parameters</source>
        <translation>Aktuelle Parameter</translation>
    </message>
    <message>
        <source>Start again</source>
        <translation>Neu beginnen</translation>
    </message>
    <message>
        <source>Keep the current ones</source>
        <translation>Die aktuellen behalten</translation>
    </message>
    <message>
        <source>Tuned parameters</source>
        <translation>Optimierte Parameter</translation>
    </message>
    <message>
        <source>Beware: the tuned parameters change the strides, not only the figure (a swing split in two or a stance lost looks like this):</source>
        <translation>Achtung: die optimierten Parameter ändern die Doppelschritte, nicht nur die Kennzahl (so sieht eine zweigeteilte Schwungphase oder eine verlorene Standphase aus):</translation>
    </message>
</context>
<context>
    <name>footpath::TuneFolderDialog</name>
    <message>
        <source>%1: no samples</source>
        <translation>%1: keine Abtastwerte</translation>
    </message>
    <message>
        <source>Tune over a folder</source>
        <translation>Über einen Ordner optimieren</translation>
    </message>
    <message>
        <source>Choose a folder of recordings of one sensor and one way of walking.</source>
        <translation>Wählen Sie einen Ordner mit Aufzeichnungen eines Sensors und einer Gangart.</translation>
    </message>
    <message>
        <source>Choose...</source>
        <translation>Auswählen...</translation>
    </message>
    <message>
        <source>Detect (headerless files: the usual columns)</source>
        <translation>Erkennen (Dateien ohne Kopfzeile: die üblichen Spalten)</translation>
    </message>
    <message>
        <source>How to read files that do not describe themselves</source>
        <translation>Wie Dateien gelesen werden, die sich nicht selbst beschreiben</translation>
    </message>
    <message>
        <source>Every walk ends where it started</source>
        <translation>Jeder Gang endet, wo er begann</translation>
    </message>
    <message>
        <source>Score every recording by its end-to-start distance, also those not marked closed</source>
        <translation>Jede Aufzeichnung nach ihrem Abstand Ende–Start bewerten, auch die nicht als geschlossen markierten</translation>
    </message>
    <message>
        <source>Folder:</source>
        <translation>Ordner:</translation>
    </message>
    <message>
        <source>Read with:</source>
        <translation>Lesen mit:</translation>
    </message>
    <message>
        <source>Parameter sets to try, each on every recording</source>
        <translation>Zu probierende Parametersätze, jeder auf jeder Aufzeichnung</translation>
    </message>
    <message>
        <source>Evaluations:</source>
        <translation>Auswertungen:</translation>
    </message>
    <message numerus="yes">
        <source>on %n core(s)</source>
        <translation>
            <numerusform>auf %n Kern</numerusform>
            <numerusform>auf %n Kernen</numerusform>
        </translation>
    </message>
    <message>
        <source>%v of %m evaluations</source>
        <translation>%v von %m Auswertungen</translation>
    </message>
    <message>
        <source>Recording</source>
        <translation>Aufzeichnung</translation>
    </message>
    <message>
        <source>Before</source>
        <translation>Vorher</translation>
    </message>
    <message>
        <source>After</source>
        <translation>Nachher</translation>
    </message>
    <message>
        <source>What changed</source>
        <translation>Was sich geändert hat</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>Stop searching and keep the best parameters found so far</source>
        <translation>Die Suche beenden und die bisher besten Parameter behalten</translation>
    </message>
    <message>
        <source>Save preset...</source>
        <translation>Voreinstellung speichern...</translation>
    </message>
    <message>
        <source>Apply to the workspace</source>
        <translation>Auf den Arbeitsbereich anwenden</translation>
    </message>
    <message>
        <source>Make them the workspace&apos;s parameters (Edit &gt; Undo brings the current ones back)</source>
        <translation>Sie zu den Parametern des Arbeitsbereichs machen (Bearbeiten &gt; Rückgängig holt die aktuellen zurück)</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <source>Folder of recordings</source>
        <translation>Ordner mit Aufzeichnungen</translation>
    </message>
    <message>
        <source>Reading the recordings in %1...</source>
        <translation>Lese die Aufzeichnungen in %1...</translation>
    </message>
    <message>
        <source>No recording could be read in this folder.</source>
        <translation>In diesem Ordner konnte keine Aufzeichnung gelesen werden.</translation>
    </message>
    <message numerus="yes">
        <source>%n recording(s) read. Choose what to minimise and start.</source>
        <translation>
            <numerusform>%n Aufzeichnung gelesen. Wählen Sie, was minimiert werden soll, und starten Sie.</numerusform>
            <numerusform>%n Aufzeichnungen gelesen. Wählen Sie, was minimiert werden soll, und starten Sie.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Not read (%n file(s)):</source>
        <translation>
            <numerusform>Nicht gelesen (%n Datei):</numerusform>
            <numerusform>Nicht gelesen (%n Dateien):</numerusform>
        </translation>
    </message>
    <message>
        <source>no recordings read yet</source>
        <translation>noch keine Aufzeichnungen gelesen</translation>
    </message>
    <message>
        <source>no walk is marked closed: tick it if they all end where they started</source>
        <translation>kein Gang ist als geschlossen markiert: ankreuzen, wenn alle enden, wo sie begannen</translation>
    </message>
    <message>
        <source>no recording has a known length (e.g. walk_72m.txt, or a sidecar)</source>
        <translation>keine Aufzeichnung hat eine bekannte Länge (z. B. walk_72m.txt, oder eine Begleitdatei)</translation>
    </message>
    <message>
        <source>no recording has reference positions</source>
        <translation>keine Aufzeichnung hat Referenzpositionen</translation>
    </message>
    <message>
        <source>None of the recordings has what this criterion needs.</source>
        <translation>Keine der Aufzeichnungen hat, was dieses Kriterium benötigt.</translation>
    </message>
    <message numerus="yes">
        <source>Tuning on %n recording(s): the current parameters, then a spread over the whole range...</source>
        <translation>
            <numerusform>Optimiere auf %n Aufzeichnung: die aktuellen Parameter, dann eine Streuung über den ganzen Bereich...</numerusform>
            <numerusform>Optimiere auf %n Aufzeichnungen: die aktuellen Parameter, dann eine Streuung über den ganzen Bereich...</numerusform>
        </translation>
    </message>
    <message>
        <source>Stopping; the best parameters so far are kept...</source>
        <translation>Wird beendet; die bisher besten Parameter werden behalten...</translation>
    </message>
    <message>
        <source>Best mean so far: %1</source>
        <translation>Bester Mittelwert bisher: %1</translation>
    </message>
    <message>
        <source>Searching around the best parameters found so far...</source>
        <translation>Suche um die bisher besten Parameter...</translation>
    </message>
    <message>
        <source>Best mean: %1</source>
        <translation>Bester Mittelwert: %1</translation>
    </message>
    <message numerus="yes">
        <source>Stopped after %n evaluation(s).</source>
        <translation>
            <numerusform>Angehalten nach %n Auswertung.</numerusform>
            <numerusform>Angehalten nach %n Auswertungen.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Done: %n evaluation(s).</source>
        <translation>
            <numerusform>Fertig: %n Auswertung.</numerusform>
            <numerusform>Fertig: %n Auswertungen.</numerusform>
        </translation>
    </message>
    <message>
        <source>No better parameters were found; the current ones stay.</source>
        <translation>Es wurden keine besseren Parameter gefunden; die aktuellen bleiben.</translation>
    </message>
    <message>
        <source>Save them as a preset, or apply them to the workspace.</source>
        <translation>Speichern Sie sie als Voreinstellung oder wenden Sie sie auf den Arbeitsbereich an.</translation>
    </message>
    <message>
        <source>Not scored: the recording lacks what the criterion needs</source>
        <translation>Nicht bewertet: der Aufzeichnung fehlt, was das Kriterium benötigt</translation>
    </message>
    <message>
        <source>Mean</source>
        <translation>Mittelwert</translation>
    </message>
    <message>
        <source>Start again</source>
        <translation>Neu beginnen</translation>
    </message>
    <message>
        <source>Save preset</source>
        <translation>Voreinstellung speichern</translation>
    </message>
    <message>
        <source>Presets (*.json)</source>
        <translation>Voreinstellungen (*.json)</translation>
    </message>
    <message>
        <source>Preset written to %1</source>
        <translation>Voreinstellung gespeichert unter %1</translation>
    </message>
    <message>
        <source>Parameters tuned over %1</source>
        <translation>Parameter optimiert über %1</translation>
    </message>
    <message>
        <source>Beware: the tuned parameters change the strides, not only the figure: %1</source>
        <translation>Achtung: die optimierten Parameter ändern die Doppelschritte, nicht nur die Kennzahl: %1</translation>
    </message>
</context>
<context>
    <name>footpath::WarningOverlay</name>
    <message>
        <source>no initial rest</source>
        <translation>keine Ruhe zu Beginn</translation>
    </message>
    <message>
        <source>missed stance</source>
        <translation>verpasste Standphase</translation>
    </message>
    <message>
        <source>stride too long</source>
        <translation>Doppelschritt zu lang</translation>
    </message>
    <message>
        <source>stride too slow</source>
        <translation>Doppelschritt zu langsam</translation>
    </message>
    <message>
        <source>stance share</source>
        <translation>Standanteil</translation>
    </message>
    <message>
        <source>foot too fast</source>
        <translation>Fuß zu schnell</translation>
    </message>
    <message>
        <source>few stances</source>
        <translation>wenige Standphasen</translation>
    </message>
    <message>
        <source>height vs barometer</source>
        <translation>Höhe gegen Barometer</translation>
    </message>
    <message>
        <source>%1–%2 s</source>
        <translation>%1–%2 s</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>Warnungen</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Foot-mounted inertial navigation</source>
        <translation>Fußmontierte Inertialnavigation</translation>
    </message>
    <message>
        <source>Save a PNG of the window once estimated, then quit</source>
        <translation>Nach der Schätzung ein PNG des Fensters speichern, dann beenden</translation>
    </message>
    <message>
        <source>Language (en, de, zh_CN)</source>
        <translation>Sprache (en, de, zh_CN)</translation>
    </message>
    <message>
        <source>Connect the live input to this serial port or emulator link</source>
        <translation>Den Live-Eingang mit dieser seriellen Schnittstelle oder Emulator-Verknüpfung verbinden</translation>
    </message>
    <message>
        <source>--set expects name=value, got &apos;%1&apos;</source>
        <translation>--set erwartet Name=Wert, erhalten: &apos;%1&apos;</translation>
    </message>
    <message>
        <source>Start with the parameters of this preset (JSON)</source>
        <translation>Mit den Parametern dieser Voreinstellung (JSON) starten</translation>
    </message>
    <message>
        <source>Set one parameter, as footpath-cli does (repeatable)</source>
        <translation>Einen Parameter setzen, wie bei footpath-cli (wiederholbar)</translation>
    </message>
    <message>
        <source>Parameters from the command line</source>
        <translation>Parameter von der Kommandozeile</translation>
    </message>
    <message>
        <source>Open the method comparison and run these sets, e.g. &quot;zupt;zupt,zaru;feliz&quot;</source>
        <translation>Den Methodenvergleich öffnen und diese Kombinationen rechnen, z. B. &quot;zupt;zupt,zaru;feliz&quot;</translation>
    </message>
    <message>
        <source>Recording to open; two files (or a folder): the left and the right foot of one walk</source>
        <translation>Zu öffnende Aufzeichnung; zwei Dateien (oder ein Ordner): der linke und der rechte Fuß eines Gangs</translation>
    </message>
    <message>
        <source>Show this view: signals, detector, states, trajectory2d, trajectory3d, motion, summary, steps or gait</source>
        <translation>Diese Ansicht zeigen: signals, detector, states, trajectory2d, trajectory3d, motion, summary, steps oder gait</translation>
    </message>
    <message>
        <source>Read the recording with this column map, as footpath-cli does (time_ms,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,...)</source>
        <translation>Die Aufzeichnung mit dieser Spaltenzuordnung lesen, wie bei footpath-cli (time_ms,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,...)</translation>
    </message>
    <message>
        <source>Read the recording with a saved import preset</source>
        <translation>Die Aufzeichnung mit einer gespeicherten Importvoreinstellung lesen</translation>
    </message>
</context>
</TS>
