<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>CamGenerator</name>
    <message>
        <source>The start position %1 is outside the range %2..%3. Enter a start inside the range.</source>
        <translation>Die Startposition %1 liegt außerhalb des Bereichs %2..%3. Geben Sie einen Start innerhalb des Bereichs ein.</translation>
    </message>
    <message>
        <source>The number of cams must be between 1 and %1.</source>
        <translation>Die Anzahl der Nocken muss zwischen 1 und %1 liegen.</translation>
    </message>
    <message>
        <source>The duty cycle must be above 0 % and below 100 %; at 100 % the cams would touch.</source>
        <translation>Das Tastverhältnis muss über 0 % und unter 100 % liegen; bei 100 % würden sich die Nocken berühren.</translation>
    </message>
    <message>
        <source>%1 cams with %2 % duty do not fit into %3 positions. Choose fewer cams or another duty cycle.</source>
        <translation>%1 Nocken mit %2 % Tastverhältnis passen nicht in %3 Positionen. Wählen Sie weniger Nocken oder ein anderes Tastverhältnis.</translation>
    </message>
    <message>
        <source>The pitch (%1) must be larger than the cam length (%2), and the length at least 1; otherwise the cams overlap.</source>
        <translation>Der Abstand (%1) muss größer als die Nockenlänge (%2) sein und die Länge mindestens 1; sonst überlappen sich die Nocken.</translation>
    </message>
    <message>
        <source>These settings make more than %1 cams, the most a track holds. Choose a larger pitch.</source>
        <translation>Diese Einstellungen ergeben mehr als %1 Nocken, mehr als eine Spur fasst. Wählen Sie einen größeren Abstand.</translation>
    </message>
    <message>
        <source>No cam of length %1 fits between %2 and %3.</source>
        <translation>Kein Nocken der Länge %1 passt zwischen %2 und %3.</translation>
    </message>
</context>
<context>
    <name>Settings</name>
    <message>
        <source>Encoder</source>
        <translation>Geber</translation>
    </message>
    <message>
        <source>The position encoder connected to the device, from the device's list of encoders, or the programmable special encoder set up on the special encoder page.</source>
        <translation>Der am Gerät angeschlossene Positionsgeber aus der Geberliste des Geräts oder der programmierbare Sondergeber, der auf der Sondergeber-Seite eingestellt wird.</translation>
    </message>
    <message>
        <source>SSI 256 Gray singleturn</source>
        <translation>SSI 256 Gray Singleturn</translation>
    </message>
    <message>
        <source>SSI 360 Gray singleturn</source>
        <translation>SSI 360 Gray Singleturn</translation>
    </message>
    <message>
        <source>SSI 512 Gray singleturn</source>
        <translation>SSI 512 Gray Singleturn</translation>
    </message>
    <message>
        <source>SSI 1000 Gray singleturn</source>
        <translation>SSI 1000 Gray Singleturn</translation>
    </message>
    <message>
        <source>SSI 1024 Gray singleturn</source>
        <translation>SSI 1024 Gray Singleturn</translation>
    </message>
    <message>
        <source>SSI 2048 Gray singleturn</source>
        <translation>SSI 2048 Gray Singleturn</translation>
    </message>
    <message>
        <source>SSI 4096 Gray singleturn</source>
        <translation>SSI 4096 Gray Singleturn</translation>
    </message>
    <message>
        <source>SSI 8192 Gray singleturn</source>
        <translation>SSI 8192 Gray Singleturn</translation>
    </message>
    <message>
        <source>Analogue SSI converter 8 bit (0..255)</source>
        <translation>Analog-SSI-Wandler 8 Bit (0..255)</translation>
    </message>
    <message>
        <source>Analogue SSI converter 12 bit (0..4095)</source>
        <translation>Analog-SSI-Wandler 12 Bit (0..4095)</translation>
    </message>
    <message>
        <source>SSI multiturn 4096 x 1 turn</source>
        <translation>SSI Multiturn 4096 x 1 Umdrehung</translation>
    </message>
    <message>
        <source>SSI multiturn 4096 x 2 turns</source>
        <translation>SSI Multiturn 4096 x 2 Umdrehungen</translation>
    </message>
    <message>
        <source>SSI multiturn 4096 x 4 turns</source>
        <translation>SSI Multiturn 4096 x 4 Umdrehungen</translation>
    </message>
    <message>
        <source>SSI multiturn 4096 x 8 turns</source>
        <translation>SSI Multiturn 4096 x 8 Umdrehungen</translation>
    </message>
    <message>
        <source>SSI multiturn 4096 x 16 turns</source>
        <translation>SSI Multiturn 4096 x 16 Umdrehungen</translation>
    </message>
    <message>
        <source>SSI multiturn 8192 x 2 turns</source>
        <translation>SSI Multiturn 8192 x 2 Umdrehungen</translation>
    </message>
    <message>
        <source>SSI multiturn 8192 x 4 turns</source>
        <translation>SSI Multiturn 8192 x 4 Umdrehungen</translation>
    </message>
    <message>
        <source>SSI multiturn 8192 x 8 turns</source>
        <translation>SSI Multiturn 8192 x 8 Umdrehungen</translation>
    </message>
    <message>
        <source>SSI multiturn 8192 x 16 turns</source>
        <translation>SSI Multiturn 8192 x 16 Umdrehungen</translation>
    </message>
    <message>
        <source>SSI multiturn 8192 x 32 turns</source>
        <translation>SSI Multiturn 8192 x 32 Umdrehungen</translation>
    </message>
    <message>
        <source>SSI multiturn 8192 x 64 turns</source>
        <translation>SSI Multiturn 8192 x 64 Umdrehungen</translation>
    </message>
    <message>
        <source>Programmable special encoder</source>
        <translation>Programmierbarer Sondergeber</translation>
    </message>
    <message>
        <source>Encoder text line 1</source>
        <translation>Gebertext Zeile 1</translation>
    </message>
    <message>
        <source>First text line describing the selected encoder, as the device shows it.</source>
        <translation>Erste Textzeile zum gewählten Geber, wie das Gerät sie anzeigt.</translation>
    </message>
    <message>
        <source>Encoder text line 2</source>
        <translation>Gebertext Zeile 2</translation>
    </message>
    <message>
        <source>Second text line describing the selected encoder, as the device shows it.</source>
        <translation>Zweite Textzeile zum gewählten Geber, wie das Gerät sie anzeigt.</translation>
    </message>
    <message>
        <source>Actual value hysteresis</source>
        <translation>Istwert-Hysterese</translation>
    </message>
    <message>
        <source>Change of the encoder value that is ignored, so that a shaft standing on an edge does not make the outputs flicker.</source>
        <translation>Änderung des Geberwerts, die ignoriert wird, damit eine auf einer Flanke stehende Welle die Ausgänge nicht flackern lässt.</translation>
    </message>
    <message>
        <source>increments</source>
        <translation>Inkremente</translation>
    </message>
    <message>
        <source>Maximum increments per cycle</source>
        <translation>Höchste Inkremente pro Zyklus</translation>
    </message>
    <message>
        <source>Largest plausible change of the encoder value within one cycle; a bigger jump is reported as an encoder error. 0 switches the check off.</source>
        <translation>Größte plausible Änderung des Geberwerts innerhalb eines Zyklus; ein größerer Sprung wird als Geberfehler gemeldet. 0 schaltet die Prüfung ab.</translation>
    </message>
    <message>
        <source>Gear multiplier</source>
        <translation>Getriebe-Multiplikator</translation>
    </message>
    <message>
        <source>The encoder value is multiplied by this factor and divided by the gear divisor. A negative factor reverses the direction; 0 is not allowed.</source>
        <translation>Der Geberwert wird mit diesem Faktor multipliziert und durch den Getriebe-Divisor geteilt. Ein negativer Faktor kehrt die Richtung um; 0 ist nicht erlaubt.</translation>
    </message>
    <message>
        <source>Gear divisor</source>
        <translation>Getriebe-Divisor</translation>
    </message>
    <message>
        <source>The encoder value multiplied by the gear multiplier is divided by this number.</source>
        <translation>Der mit dem Getriebe-Multiplikator multiplizierte Geberwert wird durch diese Zahl geteilt.</translation>
    </message>
    <message>
        <source>Actual value format</source>
        <translation>Istwert-Format</translation>
    </message>
    <message>
        <source>How the device displays the actual value (format text, e.g. the position of the decimal point and the unit).</source>
        <translation>Wie das Gerät den Istwert anzeigt (Formattext, z. B. Lage des Dezimalpunkts und die Einheit).</translation>
    </message>
    <message>
        <source>Special encoder type</source>
        <translation>Sondergeber-Typ</translation>
    </message>
    <message>
        <source>Which kind of programmable special encoder is set up (5 = timer). Chosen by writing one of the parameter pages.</source>
        <translation>Welche Art programmierbarer Sondergeber eingestellt ist (5 = Timer). Wird durch Schreiben einer der Parameterseiten gewählt.</translation>
    </message>
    <message>
        <source>Special encoder text line 1</source>
        <translation>Sondergeber-Text Zeile 1</translation>
    </message>
    <message>
        <source>First text line the device shows for the special encoder.</source>
        <translation>Erste Textzeile, die das Gerät für den Sondergeber anzeigt.</translation>
    </message>
    <message>
        <source>Special encoder text line 2</source>
        <translation>Sondergeber-Text Zeile 2</translation>
    </message>
    <message>
        <source>Second text line the device shows for the special encoder.</source>
        <translation>Zweite Textzeile, die das Gerät für den Sondergeber anzeigt.</translation>
    </message>
    <message>
        <source>SSI resolution</source>
        <translation>SSI-Auflösung</translation>
    </message>
    <message>
        <source>Number of data bits the SSI encoder sends per value.</source>
        <translation>Anzahl der Datenbits, die der SSI-Geber je Wert sendet.</translation>
    </message>
    <message>
        <source>bits</source>
        <translation>Bit</translation>
    </message>
    <message>
        <source>SSI first bit</source>
        <translation>SSI erstes Bit</translation>
    </message>
    <message>
        <source>Position of the first valid bit in the SSI telegram.</source>
        <translation>Lage des ersten gültigen Bits im SSI-Telegramm.</translation>
    </message>
    <message>
        <source>SSI capping</source>
        <translation>SSI-Kappung</translation>
    </message>
    <message>
        <source>Number of low bits cut off the SSI value.</source>
        <translation>Anzahl der niederwertigen Bits, die vom SSI-Wert abgeschnitten werden.</translation>
    </message>
    <message>
        <source>SSI error bit</source>
        <translation>SSI-Fehlerbit</translation>
    </message>
    <message>
        <source>Bit of the SSI telegram that signals an encoder error (0 = none).</source>
        <translation>Bit des SSI-Telegramms, das einen Geberfehler meldet (0 = keines).</translation>
    </message>
    <message>
        <source>Parallel encoder resolution</source>
        <translation>Auflösung Parallelgeber</translation>
    </message>
    <message>
        <source>Increments per turn of the parallel encoder.</source>
        <translation>Inkremente pro Umdrehung des Parallelgebers.</translation>
    </message>
    <message>
        <source>Parallel encoder first input</source>
        <translation>Erster Eingang Parallelgeber</translation>
    </message>
    <message>
        <source>First of the inputs the parallel encoder is wired to.</source>
        <translation>Erster der Eingänge, an die der Parallelgeber angeschlossen ist.</translation>
    </message>
    <message>
        <source>Parallel encoder code</source>
        <translation>Code Parallelgeber</translation>
    </message>
    <message>
        <source>Whether the parallel encoder sends Gray code or binary.</source>
        <translation>Ob der Parallelgeber Gray-Code oder binär sendet.</translation>
    </message>
    <message>
        <source>Gray code</source>
        <translation>Gray-Code</translation>
    </message>
    <message>
        <source>Binary</source>
        <translation>Binär</translation>
    </message>
    <message>
        <source>Incremental encoder resolution</source>
        <translation>Auflösung Inkrementalgeber</translation>
    </message>
    <message>
        <source>Increments per turn of the incremental encoder.</source>
        <translation>Inkremente pro Umdrehung des Inkrementalgebers.</translation>
    </message>
    <message>
        <source>Incremental encoder divider</source>
        <translation>Teiler Inkrementalgeber</translation>
    </message>
    <message>
        <source>The incremental pulses are divided by this number.</source>
        <translation>Die Inkrementalimpulse werden durch diese Zahl geteilt.</translation>
    </message>
    <message>
        <source>Incremental encoder clear mode</source>
        <translation>Löschart Inkrementalgeber</translation>
    </message>
    <message>
        <source>When the incremental counter is cleared (device-specific code).</source>
        <translation>Wann der Inkrementalzähler gelöscht wird (gerätespezifischer Code).</translation>
    </message>
    <message>
        <source>Multiturn resolution</source>
        <translation>Multiturn-Auflösung</translation>
    </message>
    <message>
        <source>Increments per turn of the multiturn encoder.</source>
        <translation>Inkremente pro Umdrehung des Multiturn-Gebers.</translation>
    </message>
    <message>
        <source>Multiturn turns</source>
        <translation>Multiturn-Umdrehungen</translation>
    </message>
    <message>
        <source>Number of turns the multiturn encoder counts.</source>
        <translation>Anzahl der Umdrehungen, die der Multiturn-Geber zählt.</translation>
    </message>
    <message>
        <source>turns</source>
        <translation>Umdrehungen</translation>
    </message>
    <message>
        <source>Multiturn divider</source>
        <translation>Multiturn-Teiler</translation>
    </message>
    <message>
        <source>The multiturn value is divided by this number.</source>
        <translation>Der Multiturn-Wert wird durch diese Zahl geteilt.</translation>
    </message>
    <message>
        <source>PLL pulses per input pulse</source>
        <translation>PLL-Impulse je Eingangsimpuls</translation>
    </message>
    <message>
        <source>Increments the PLL generates for each input pulse.</source>
        <translation>Inkremente, die die PLL für jeden Eingangsimpuls erzeugt.</translation>
    </message>
    <message>
        <source>PLL pulses per turn</source>
        <translation>PLL-Impulse pro Umdrehung</translation>
    </message>
    <message>
        <source>Input pulses per turn of the machine.</source>
        <translation>Eingangsimpulse pro Umdrehung der Maschine.</translation>
    </message>
    <message>
        <source>PLL error window</source>
        <translation>PLL-Fehlerfenster</translation>
    </message>
    <message>
        <source>Deviation from the expected pulse count that is still accepted.</source>
        <translation>Abweichung von der erwarteten Impulszahl, die noch angenommen wird.</translation>
    </message>
    <message>
        <source>PLL pulse input</source>
        <translation>PLL-Impulseingang</translation>
    </message>
    <message>
        <source>Input that receives the PLL's pulses.</source>
        <translation>Eingang, der die Impulse der PLL empfängt.</translation>
    </message>
    <message>
        <source>PLL clear input</source>
        <translation>PLL-Löscheingang</translation>
    </message>
    <message>
        <source>Input that clears the PLL's position (0 = none).</source>
        <translation>Eingang, der die Position der PLL löscht (0 = keiner).</translation>
    </message>
    <message>
        <source>PLL sync output</source>
        <translation>PLL-Synchronausgang</translation>
    </message>
    <message>
        <source>Output that signals that the PLL is synchronised (0 = none).</source>
        <translation>Ausgang, der meldet, dass die PLL synchron ist (0 = keiner).</translation>
    </message>
    <message>
        <source>Timer step time</source>
        <translation>Timer-Schrittzeit</translation>
    </message>
    <message>
        <source>Time after which the timer encoder counts one step.</source>
        <translation>Zeit, nach der der Timer-Geber einen Schritt weiterzählt.</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <source>Timer resolution</source>
        <translation>Timer-Auflösung</translation>
    </message>
    <message>
        <source>Steps of the timer encoder before it starts again at zero.</source>
        <translation>Schritte des Timer-Gebers, bevor er wieder bei null beginnt.</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>Schritte</translation>
    </message>
    <message>
        <source>Timer hold input</source>
        <translation>Timer-Halteeingang</translation>
    </message>
    <message>
        <source>Input that holds the timer encoder (0 = none).</source>
        <translation>Eingang, der den Timer-Geber anhält (0 = keiner).</translation>
    </message>
    <message>
        <source>Timer clear input</source>
        <translation>Timer-Löscheingang</translation>
    </message>
    <message>
        <source>Input that sets the timer encoder back to zero (0 = none).</source>
        <translation>Eingang, der den Timer-Geber auf null zurücksetzt (0 = keiner).</translation>
    </message>
    <message>
        <source>Axis type</source>
        <translation>Achsart</translation>
    </message>
    <message>
        <source>Rotary: the actual value runs round and cams may wrap through zero. Linear: the actual value runs from the start value upwards.</source>
        <translation>Rund: der Istwert läuft im Kreis und Nocken dürfen über null gehen. Linear: der Istwert läuft vom Startwert aufwärts.</translation>
    </message>
    <message>
        <source>Rotary</source>
        <translation>Rund</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>Linear</translation>
    </message>
    <message>
        <source>Linear start value</source>
        <translation>Linearer Startwert</translation>
    </message>
    <message>
        <source>Actual value at the start of a linear axis.</source>
        <translation>Istwert am Anfang einer Linearachse.</translation>
    </message>
    <message>
        <source>Offset</source>
        <translation>Offset</translation>
    </message>
    <message>
        <source>Zero-point shift added to the encoder value.</source>
        <translation>Nullpunktverschiebung, die zum Geberwert addiert wird.</translation>
    </message>
    <message>
        <source>Preset value</source>
        <translation>Preset-Wert</translation>
    </message>
    <message>
        <source>Actual value the device takes when the preset input switches on.</source>
        <translation>Istwert, den das Gerät übernimmt, wenn der Preset-Eingang einschaltet.</translation>
    </message>
    <message>
        <source>Preset input</source>
        <translation>Preset-Eingang</translation>
    </message>
    <message>
        <source>Input that sets the actual value to the preset value (0 = none).</source>
        <translation>Eingang, der den Istwert auf den Preset-Wert setzt (0 = keiner).</translation>
    </message>
    <message>
        <source>Preset retained at power-off</source>
        <translation>Preset nullspannungssicher</translation>
    </message>
    <message>
        <source>Whether a preset survives switching the device off and on (zero-voltage safe).</source>
        <translation>Ob ein Preset das Aus- und Einschalten des Geräts überdauert (nullspannungssicher).</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <source>On</source>
        <translation>Ein</translation>
    </message>
    <message>
        <source>Speed factor</source>
        <translation>Geschwindigkeitsfaktor</translation>
    </message>
    <message>
        <source>The measured speed is multiplied by this factor before it is displayed (0.00001 to 999.99999).</source>
        <translation>Die gemessene Geschwindigkeit wird vor der Anzeige mit diesem Faktor multipliziert (0,00001 bis 999,99999).</translation>
    </message>
    <message>
        <source>Speed format</source>
        <translation>Geschwindigkeitsformat</translation>
    </message>
    <message>
        <source>How the device displays the speed (format text).</source>
        <translation>Wie das Gerät die Geschwindigkeit anzeigt (Formattext).</translation>
    </message>
    <message>
        <source>100% speed value</source>
        <translation>100-%-Geschwindigkeitswert</translation>
    </message>
    <message>
        <source>Speed value that counts as 100 %, e.g. for the analogue speed output.</source>
        <translation>Geschwindigkeitswert, der als 100 % gilt, z. B. für den analogen Geschwindigkeitsausgang.</translation>
    </message>
    <message>
        <source>Speed accuracy</source>
        <translation>Geschwindigkeitsgenauigkeit</translation>
    </message>
    <message>
        <source>Resolution of the speed measurement (0.01 to 9.99).</source>
        <translation>Auflösung der Geschwindigkeitsmessung (0,01 bis 9,99).</translation>
    </message>
    <message>
        <source>Display mode</source>
        <translation>Anzeigeart</translation>
    </message>
    <message>
        <source>What the display shows: automatic change, speed or position. With speed or position an input can switch the display.</source>
        <translation>Was die Anzeige zeigt: automatischer Wechsel, Geschwindigkeit oder Position. Bei Geschwindigkeit oder Position kann ein Eingang die Anzeige umschalten.</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatisch</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <source>Display switch input</source>
        <translation>Eingang Anzeigeumschaltung</translation>
    </message>
    <message>
        <source>Input that switches the display between speed and position (0 = none; only in display mode Speed or Position).</source>
        <translation>Eingang, der die Anzeige zwischen Geschwindigkeit und Position umschaltet (0 = keiner; nur bei Anzeigeart Geschwindigkeit oder Position).</translation>
    </message>
    <message>
        <source>Cable length</source>
        <translation>Kabellänge</translation>
    </message>
    <message>
        <source>Length of the encoder cable; the device compensates the signal delay.</source>
        <translation>Länge des Geberkabels; das Gerät gleicht die Signallaufzeit aus.</translation>
    </message>
    <message>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <source>Minimum cycle time</source>
        <translation>Kleinste Zykluszeit</translation>
    </message>
    <message>
        <source>Shortest time of one device cycle, in 0.1 ms steps (0 to 10000 ms).</source>
        <translation>Kürzeste Zeit eines Gerätezyklus, in Schritten von 0,1 ms (0 bis 10000 ms).</translation>
    </message>
    <message>
        <source>0.1 ms</source>
        <translation>0,1 ms</translation>
    </message>
    <message>
        <source>Current cycle time</source>
        <translation>Aktuelle Zykluszeit</translation>
    </message>
    <message>
        <source>Time the device currently needs for one cycle, in 0.1 ms steps.</source>
        <translation>Zeit, die das Gerät zurzeit für einen Zyklus braucht, in Schritten von 0,1 ms.</translation>
    </message>
    <message>
        <source>Safety output</source>
        <translation>Sicherheitsausgang</translation>
    </message>
    <message>
        <source>Output that is on while the device works without error (0 = none).</source>
        <translation>Ausgang, der eingeschaltet ist, solange das Gerät fehlerfrei arbeitet (0 = keiner).</translation>
    </message>
    <message>
        <source>Actual value output</source>
        <translation>Istwertausgabe</translation>
    </message>
    <message>
        <source>Whether and how the device passes its actual value on through outputs.</source>
        <translation>Ob und wie das Gerät seinen Istwert über Ausgänge weitergibt.</translation>
    </message>
    <message>
        <source>Do not send</source>
        <translation>Nicht senden</translation>
    </message>
    <message>
        <source>Send in Gray code</source>
        <translation>Im Gray-Code senden</translation>
    </message>
    <message>
        <source>Send in binary</source>
        <translation>Binär senden</translation>
    </message>
    <message>
        <source>Send for DC115 master-slave</source>
        <translation>Für DC115 Master-Slave senden</translation>
    </message>
    <message>
        <source>Direction output</source>
        <translation>Richtungsausgang</translation>
    </message>
    <message>
        <source>Output that shows the direction of rotation (0 = none).</source>
        <translation>Ausgang, der die Drehrichtung anzeigt (0 = keiner).</translation>
    </message>
    <message>
        <source>Standstill output</source>
        <translation>Stillstandsausgang</translation>
    </message>
    <message>
        <source>Output that switches when the axis stands still (0 = no standstill detection).</source>
        <translation>Ausgang, der schaltet, wenn die Achse stillsteht (0 = keine Stillstandserkennung).</translation>
    </message>
    <message>
        <source>Standstill speed hysteresis</source>
        <translation>Stillstands-Geschwindigkeitshysterese</translation>
    </message>
    <message>
        <source>Speed below which the axis counts as standing still.</source>
        <translation>Geschwindigkeit, unter der die Achse als stillstehend gilt.</translation>
    </message>
    <message>
        <source>Analogue speed output</source>
        <translation>Analoger Geschwindigkeitsausgang</translation>
    </message>
    <message>
        <source>Whether the device puts out the speed as an analogue value.</source>
        <translation>Ob das Gerät die Geschwindigkeit als Analogwert ausgibt.</translation>
    </message>
    <message>
        <source>Analogue cam outputs</source>
        <translation>Analoge Nockenausgänge</translation>
    </message>
    <message>
        <source>Number of analogue cam outputs in use.</source>
        <translation>Anzahl der benutzten analogen Nockenausgänge.</translation>
    </message>
    <message>
        <source>Inputs</source>
        <translation>Eingänge</translation>
    </message>
    <message>
        <source>Number of inputs the device has (multiples of 8).</source>
        <translation>Anzahl der Eingänge des Geräts (Vielfache von 8).</translation>
    </message>
    <message>
        <source>Outputs</source>
        <translation>Ausgänge</translation>
    </message>
    <message>
        <source>Number of outputs the device has (multiples of 8, 8 to 200).</source>
        <translation>Anzahl der Ausgänge des Geräts (Vielfache von 8, 8 bis 200).</translation>
    </message>
    <message>
        <source>Dead-time outputs</source>
        <translation>Totzeit-Ausgänge</translation>
    </message>
    <message>
        <source>Number of outputs with dead-time compensation, counted from output 1 (multiples of 8).</source>
        <translation>Anzahl der Ausgänge mit Totzeitkompensation, ab Ausgang 1 gezählt (Vielfache von 8).</translation>
    </message>
    <message>
        <source>Keyboard lock input</source>
        <translation>Eingang Tastatursperre</translation>
    </message>
    <message>
        <source>Input that locks the device's keyboard (0 = none).</source>
        <translation>Eingang, der die Tastatur des Geräts sperrt (0 = keiner).</translation>
    </message>
    <message>
        <source>External program selection inputs</source>
        <translation>Eingänge externe Programmwahl</translation>
    </message>
    <message>
        <source>Number of inputs that select the program in binary (0 = no external program selection).</source>
        <translation>Anzahl der Eingänge, die das Programm binär wählen (0 = keine externe Programmwahl).</translation>
    </message>
    <message>
        <source>First program selection input</source>
        <translation>Erster Programmwahl-Eingang</translation>
    </message>
    <message>
        <source>First of the inputs that select the program (0 = none).</source>
        <translation>Erster der Eingänge, die das Programm wählen (0 = keiner).</translation>
    </message>
    <message>
        <source>Program selection mode</source>
        <translation>Programmwahl-Art</translation>
    </message>
    <message>
        <source>When a newly selected program takes effect: slowly, within one cycle, or when the axis passes the program selection actual value.</source>
        <translation>Wann ein neu gewähltes Programm wirkt: langsam, innerhalb eines Zyklus oder wenn die Achse den Programmwahl-Istwert überfährt.</translation>
    </message>
    <message>
        <source>Slow</source>
        <translation>Langsam</translation>
    </message>
    <message>
        <source>Within one cycle</source>
        <translation>Innerhalb eines Zyklus</translation>
    </message>
    <message>
        <source>At actual value</source>
        <translation>Bei Istwert</translation>
    </message>
    <message>
        <source>Program selection actual value</source>
        <translation>Programmwahl-Istwert</translation>
    </message>
    <message>
        <source>Actual value at which a new program takes effect (mode "At actual value" only).</source>
        <translation>Istwert, bei dem ein neues Programm wirkt (nur Art „Bei Istwert“).</translation>
    </message>
    <message>
        <source>Communication protocol</source>
        <translation>Kommunikationsprotokoll</translation>
    </message>
    <message>
        <source>Protocol of the serial interface. Changing it ends the connection with the current protocol.</source>
        <translation>Protokoll der seriellen Schnittstelle. Eine Änderung beendet die Verbindung mit dem jetzigen Protokoll.</translation>
    </message>
    <message>
        <source>Cam-BUS</source>
        <translation>Cam-BUS</translation>
    </message>
    <message>
        <source>Standard</source>
        <translation>Standard</translation>
    </message>
    <message>
        <source>Multiuser</source>
        <translation>Multiuser</translation>
    </message>
    <message>
        <source>S5-L1</source>
        <translation>S5-L1</translation>
    </message>
    <message>
        <source>3964R</source>
        <translation>3964R</translation>
    </message>
    <message>
        <source>Device number</source>
        <translation>Gerätenummer</translation>
    </message>
    <message>
        <source>Number of the device on a Multiuser or Cam-BUS line.</source>
        <translation>Nummer des Geräts an einer Multiuser- oder Cam-BUS-Leitung.</translation>
    </message>
    <message>
        <source>Analogue outputs</source>
        <translation>Analogausgänge</translation>
    </message>
    <message>
        <source>How many internal analogue outputs are in use.</source>
        <translation>Wie viele interne Analogausgänge benutzt werden.</translation>
    </message>
    <message>
        <source>No analogue value</source>
        <translation>Kein Analogwert</translation>
    </message>
    <message>
        <source>1 internal analogue output</source>
        <translation>1 interner Analogausgang</translation>
    </message>
    <message>
        <source>2 internal analogue outputs</source>
        <translation>2 interne Analogausgänge</translation>
    </message>
    <message>
        <source>Analogue 1 offset</source>
        <translation>Analog 1 Offset</translation>
    </message>
    <message>
        <source>Offset adjustment of analogue value 1.</source>
        <translation>Offsetabgleich von Analogwert 1.</translation>
    </message>
    <message>
        <source>Analogue 2 offset</source>
        <translation>Analog 2 Offset</translation>
    </message>
    <message>
        <source>Offset adjustment of analogue value 2.</source>
        <translation>Offsetabgleich von Analogwert 2.</translation>
    </message>
    <message>
        <source>Analogue 1 factor</source>
        <translation>Analog 1 Faktor</translation>
    </message>
    <message>
        <source>Gain adjustment of analogue value 1.</source>
        <translation>Verstärkungsabgleich von Analogwert 1.</translation>
    </message>
    <message>
        <source>Analogue 2 factor</source>
        <translation>Analog 2 Faktor</translation>
    </message>
    <message>
        <source>Gain adjustment of analogue value 2.</source>
        <translation>Verstärkungsabgleich von Analogwert 2.</translation>
    </message>
    <message>
        <source>Terminal mode</source>
        <translation>Terminalbetrieb</translation>
    </message>
    <message>
        <source>Normal operation or terminal operation of the device.</source>
        <translation>Normalbetrieb oder Terminalbetrieb des Geräts.</translation>
    </message>
    <message>
        <source>Normal</source>
        <translation>Normal</translation>
    </message>
    <message>
        <source>Terminal</source>
        <translation>Terminal</translation>
    </message>
    <message>
        <source>Device language</source>
        <translation>Gerätesprache</translation>
    </message>
    <message>
        <source>Language of the device's display: 0 German, 1 English, 2 French; further numbers depend on the firmware.</source>
        <translation>Sprache der Geräteanzeige: 0 Deutsch, 1 Englisch, 2 Französisch; weitere Nummern hängen von der Firmware ab.</translation>
    </message>
    <message>
        <source>PLC accelerator</source>
        <translation>SPS-Beschleuniger</translation>
    </message>
    <message>
        <source>Whether the PLC accelerator hardware is fitted.</source>
        <translation>Ob die Hardware des SPS-Beschleunigers bestückt ist.</translation>
    </message>
    <message>
        <source>Not fitted</source>
        <translation>Nicht bestückt</translation>
    </message>
    <message>
        <source>Fitted</source>
        <translation>Bestückt</translation>
    </message>
    <message>
        <source>PLC module</source>
        <translation>SPS-Modul</translation>
    </message>
    <message>
        <source>Switches the PLC module off or on; "flags retained" keeps the flags at power-off.</source>
        <translation>Schaltet das SPS-Modul aus oder ein; „Merker remanent“ behält die Merker beim Ausschalten.</translation>
    </message>
    <message>
        <source>On, flags retained</source>
        <translation>Ein, Merker remanent</translation>
    </message>
    <message>
        <source>PLC inputs</source>
        <translation>SPS-Eingänge</translation>
    </message>
    <message>
        <source>Number of PLC inputs (multiples of 8).</source>
        <translation>Anzahl der SPS-Eingänge (Vielfache von 8).</translation>
    </message>
    <message>
        <source>PLC outputs</source>
        <translation>SPS-Ausgänge</translation>
    </message>
    <message>
        <source>Number of PLC outputs (multiples of 8).</source>
        <translation>Anzahl der SPS-Ausgänge (Vielfache von 8).</translation>
    </message>
    <message>
        <source>PLC flags</source>
        <translation>SPS-Merker</translation>
    </message>
    <message>
        <source>Number of PLC flags (M, multiples of 8).</source>
        <translation>Anzahl der SPS-Merker (M, Vielfache von 8).</translation>
    </message>
    <message>
        <source>PLC X flags</source>
        <translation>SPS-X-Merker</translation>
    </message>
    <message>
        <source>Number of PLC X flags (multiples of 8).</source>
        <translation>Anzahl der SPS-X-Merker (Vielfache von 8).</translation>
    </message>
    <message>
        <source>PLC timers and counters</source>
        <translation>SPS-Timer und -Zähler</translation>
    </message>
    <message>
        <source>Number of PLC timers and counters (multiples of 8).</source>
        <translation>Anzahl der SPS-Timer und -Zähler (Vielfache von 8).</translation>
    </message>
    <message>
        <source>PLC V inputs</source>
        <translation>SPS-V-Eingänge</translation>
    </message>
    <message>
        <source>Number of PLC V inputs (multiples of 8).</source>
        <translation>Anzahl der SPS-V-Eingänge (Vielfache von 8).</translation>
    </message>
    <message>
        <source>PLC S inputs</source>
        <translation>SPS-S-Eingänge</translation>
    </message>
    <message>
        <source>Number of PLC S inputs (multiples of 8).</source>
        <translation>Anzahl der SPS-S-Eingänge (Vielfache von 8).</translation>
    </message>
</context>
<context>
    <name>WriteReport</name>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1 written, %2 unchanged, %3 failed</source>
        <translation>%1 geschrieben, %2 unverändert, %3 fehlgeschlagen</translation>
    </message>
    <message>
        <source>Not written (the device keeps its old values):</source>
        <translation>Nicht geschrieben (das Gerät behält seine alten Werte):</translation>
    </message>
</context>
<context>
    <name>cambench::AccessGridModel</name>
    <message>
        <source>Output %1: allowed (the user may change all outputs)</source>
        <translation>Ausgang %1: erlaubt (der Benutzer darf alle Ausgänge ändern)</translation>
    </message>
    <message>
        <source>Output %1</source>
        <translation>Ausgang %1</translation>
    </message>
</context>
<context>
    <name>cambench::BackupPage</name>
    <message>
        <source>&lt;h3&gt;Backup and restore&lt;/h3&gt;&lt;p&gt;A &lt;b&gt;backup&lt;/b&gt; copies the whole EEPROM of the device (cam programs, dead times, settings, users, PLC) block by block into a file.&lt;/p&gt;&lt;p&gt;A &lt;b&gt;restore&lt;/b&gt; erases the device and writes such a file back. CamBench checks the file first, asks for a confirmation when it comes from a different device, and saves what the device holds now into a safety backup before it erases anything.&lt;/p&gt;&lt;p&gt;If a restore is interrupted, the device stays erased and does not run until an image is restored completely: keep the safety backup.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Sichern und Wiederherstellen&lt;/h3&gt;&lt;p&gt;Eine &lt;b&gt;Sicherung&lt;/b&gt; kopiert das ganze EEPROM des Geräts (Nockenprogramme, Totzeiten, Einstellungen, Benutzer, SPS) Block für Block in eine Datei.&lt;/p&gt;&lt;p&gt;Eine &lt;b&gt;Wiederherstellung&lt;/b&gt; löscht das Gerät und schreibt eine solche Datei zurück. CamBench prüft die Datei vorher, fragt nach einer Bestätigung, wenn sie von einem anderen Gerät stammt, und sichert den jetzigen Inhalt des Geräts in eine Sicherheitskopie, bevor es etwas löscht.&lt;/p&gt;&lt;p&gt;Wird eine Wiederherstellung unterbrochen, bleibt das Gerät gelöscht und läuft nicht, bis ein Abbild vollständig wiederhergestellt ist: Bewahren Sie die Sicherheitskopie auf.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Backup or restore…</source>
        <translation>Sichern oder wiederherstellen…</translation>
    </message>
    <message>
        <source>Backup</source>
        <translation>Sicherung</translation>
    </message>
</context>
<context>
    <name>cambench::BackupWizard</name>
    <message>
        <source>EPROM %1, device number %2, %3 outputs, %4 programs, positions %5 … %6</source>
        <translation>EPROM %1, Gerätenummer %2, %3 Ausgänge, %4 Programme, Positionen %5 … %6</translation>
    </message>
    <message>
        <source>Backup and restore</source>
        <translation>Sichern und Wiederherstellen</translation>
    </message>
    <message>
        <source>Backup or restore</source>
        <translation>Sichern oder wiederherstellen</translation>
    </message>
    <message>
        <source>A backup copies the device's whole EEPROM into a file. A restore erases the device and writes such a file back.</source>
        <translation>Eine Sicherung kopiert das ganze EEPROM des Geräts in eine Datei. Eine Wiederherstellung löscht das Gerät und schreibt eine solche Datei zurück.</translation>
    </message>
    <message>
        <source>Back up the device into a file</source>
        <translation>Gerät in eine Datei sichern</translation>
    </message>
    <message>
        <source>Restore the device from a file</source>
        <translation>Gerät aus einer Datei wiederherstellen</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Durchsuchen…</translation>
    </message>
    <message>
        <source>File:</source>
        <translation>Datei:</translation>
    </message>
    <message>
        <source>EEPROM images (*.json)</source>
        <translation>EEPROM-Abbilder (*.json)</translation>
    </message>
    <message>
        <source>Backup file</source>
        <translation>Sicherungsdatei</translation>
    </message>
    <message>
        <source>Image to restore</source>
        <translation>Wiederherzustellendes Abbild</translation>
    </message>
    <message>
        <source>Check the image</source>
        <translation>Abbild prüfen</translation>
    </message>
    <message>
        <source>The restore erases the device. Before that, CamBench saves what the device holds now into a safety backup.</source>
        <translation>Die Wiederherstellung löscht das Gerät. Vorher sichert CamBench den jetzigen Inhalt des Geräts in eine Sicherheitskopie.</translation>
    </message>
    <message>
        <source>Restore although the image comes from a different device</source>
        <translation>Wiederherstellen, obwohl das Abbild von einem anderen Gerät stammt</translation>
    </message>
    <message>
        <source>Safety backup:</source>
        <translation>Sicherheitskopie:</translation>
    </message>
    <message>
        <source>Choose a file first.</source>
        <translation>Wählen Sie zuerst eine Datei.</translation>
    </message>
    <message>
        <source>Connect to the device first.</source>
        <translation>Verbinden Sie sich zuerst mit dem Gerät.</translation>
    </message>
    <message>
        <source>This file cannot be restored: %1</source>
        <translation>Diese Datei kann nicht wiederhergestellt werden: %1</translation>
    </message>
    <message>
        <source>The image comes from a different device. Confirm that you want to restore it anyway, or choose another file.</source>
        <translation>Das Abbild stammt von einem anderen Gerät. Bestätigen Sie, dass Sie es trotzdem wiederherstellen wollen, oder wählen Sie eine andere Datei.</translation>
    </message>
    <message>
        <source>Choose where the safety backup goes.</source>
        <translation>Wählen Sie, wohin die Sicherheitskopie geschrieben wird.</translation>
    </message>
    <message numerus="yes">
        <source>Image: %1
Taken %2 with %3, %n block(s), %4 bytes.</source>
        <translation><numerusform>Abbild: %1
Erstellt %2 mit %3, %n Block, %4 Bytes.</numerusform><numerusform>Abbild: %1
Erstellt %2 mit %3, %n Blöcke, %4 Bytes.</numerusform></translation>
    </message>
    <message>
        <source>Device: %1</source>
        <translation>Gerät: %1</translation>
    </message>
    <message>
        <source>The image matches this device.</source>
        <translation>Das Abbild passt zu diesem Gerät.</translation>
    </message>
    <message>
        <source>The image does NOT match this device:</source>
        <translation>Das Abbild passt NICHT zu diesem Gerät:</translation>
    </message>
    <message>
        <source>Reading the EEPROM of the device into %1…</source>
        <translation>Das EEPROM des Geräts wird nach %1 gelesen…</translation>
    </message>
    <message>
        <source>Backup</source>
        <translation>Sicherung</translation>
    </message>
    <message>
        <source>Backup failed, no file was written: %1</source>
        <translation>Sicherung fehlgeschlagen, es wurde keine Datei geschrieben: %1</translation>
    </message>
    <message>
        <source>The device was read, but the file could not be written: %1</source>
        <translation>Das Gerät wurde gelesen, aber die Datei konnte nicht geschrieben werden: %1</translation>
    </message>
    <message numerus="yes">
        <source>Backup complete: %n block(s), %1 bytes written to %2. Nothing failed.</source>
        <translation><numerusform>Sicherung vollständig: %n Block, %1 Bytes nach %2 geschrieben. Nichts ist fehlgeschlagen.</numerusform><numerusform>Sicherung vollständig: %n Blöcke, %1 Bytes nach %2 geschrieben. Nichts ist fehlgeschlagen.</numerusform></translation>
    </message>
    <message>
        <source>Step 1 of 2: saving what the device holds now into %1…</source>
        <translation>Schritt 1 von 2: der jetzige Inhalt des Geräts wird nach %1 gesichert…</translation>
    </message>
    <message>
        <source>Safety backup</source>
        <translation>Sicherheitskopie</translation>
    </message>
    <message>
        <source>Restore NOT started, the device is unchanged: the safety backup failed: %1</source>
        <translation>Wiederherstellung NICHT begonnen, das Gerät ist unverändert: die Sicherheitskopie ist fehlgeschlagen: %1</translation>
    </message>
    <message numerus="yes">
        <source>Step 2 of 2: erasing the device and writing %n block(s)…</source>
        <translation><numerusform>Schritt 2 von 2: das Gerät wird gelöscht und %n Block geschrieben…</numerusform><numerusform>Schritt 2 von 2: das Gerät wird gelöscht und %n Blöcke geschrieben…</numerusform></translation>
    </message>
    <message>
        <source>Restore</source>
        <translation>Wiederherstellung</translation>
    </message>
    <message>
        <source>Restore FAILED: %1

The safety backup of the previous content is %2; restore it to get the device back.</source>
        <translation>Wiederherstellung FEHLGESCHLAGEN: %1

Die Sicherheitskopie des vorherigen Inhalts ist %2; stellen Sie sie wieder her, um das Gerät zurückzubekommen.</translation>
    </message>
    <message numerus="yes">
        <source>Restore complete: %n block(s) written, 0 failed. The safety backup of the previous content is %1.</source>
        <translation><numerusform>Wiederherstellung vollständig: %n Block geschrieben, 0 fehlgeschlagen. Die Sicherheitskopie des vorherigen Inhalts ist %1.</numerusform><numerusform>Wiederherstellung vollständig: %n Blöcke geschrieben, 0 fehlgeschlagen. Die Sicherheitskopie des vorherigen Inhalts ist %1.</numerusform></translation>
    </message>
    <message>
        <source>Cancel the restore? If the device is already being written, it stays ERASED until you restore an image.</source>
        <translation>Wiederherstellung abbrechen? Wird das Gerät bereits beschrieben, bleibt es GELÖSCHT, bis Sie ein Abbild wiederherstellen.</translation>
    </message>
    <message>
        <source>Cancel the backup? No file will be written.</source>
        <translation>Sicherung abbrechen? Es wird keine Datei geschrieben.</translation>
    </message>
</context>
<context>
    <name>cambench::CamDiagramWidget</name>
    <message>
        <source>Output %1, cam %2: on %3, off %4, length %5</source>
        <translation>Ausgang %1, Nocken %2: ein %3, aus %4, Länge %5</translation>
    </message>
    <message>
        <source>Changed, not yet written to the device.</source>
        <translation>Geändert, noch nicht ins Gerät geschrieben.</translation>
    </message>
    <message>
        <source>%1  %2</source>
        <translation>%1  %2</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Ausgang</translation>
    </message>
</context>
<context>
    <name>cambench::CamDocument</name>
    <message>
        <source>Change cam on output %1</source>
        <translation>Nocken auf Ausgang %1 ändern</translation>
    </message>
    <message>
        <source>Add cam to output %1</source>
        <translation>Nocken zu Ausgang %1 hinzufügen</translation>
    </message>
    <message>
        <source>Delete cam of output %1</source>
        <translation>Nocken von Ausgang %1 löschen</translation>
    </message>
    <message>
        <source>Copy output %1 to output %2 of program %3</source>
        <translation>Ausgang %1 nach Ausgang %2 von Programm %3 kopieren</translation>
    </message>
    <message>
        <source>Copy program %1 to program %2</source>
        <translation>Programm %1 nach Programm %2 kopieren</translation>
    </message>
    <message>
        <source>Generate cams on output %1</source>
        <translation>Nocken auf Ausgang %1 erzeugen</translation>
    </message>
    <message>
        <source>Rename program %1</source>
        <translation>Programm %1 umbenennen</translation>
    </message>
    <message>
        <source>Rename output %1</source>
        <translation>Ausgang %1 umbenennen</translation>
    </message>
    <message>
        <source>Change dead time of output %1</source>
        <translation>Totzeit von Ausgang %1 ändern</translation>
    </message>
</context>
<context>
    <name>cambench::CamEditorWidget</name>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <source>&amp;Read Program</source>
        <translation>Programm &amp;lesen</translation>
    </message>
    <message>
        <source>Read the current program from the device</source>
        <translation>Das aktuelle Programm aus dem Gerät lesen</translation>
    </message>
    <message>
        <source>&amp;Write Program</source>
        <translation>Programm &amp;schreiben</translation>
    </message>
    <message>
        <source>Write the current program to the device</source>
        <translation>Das aktuelle Programm ins Gerät schreiben</translation>
    </message>
    <message>
        <source>&amp;Add Cam</source>
        <translation>Nocken &amp;hinzufügen</translation>
    </message>
    <message>
        <source>Add a cam to the selected output</source>
        <translation>Dem gewählten Ausgang einen Nocken hinzufügen</translation>
    </message>
    <message>
        <source>&amp;Delete Cam</source>
        <translation>Nocken &amp;löschen</translation>
    </message>
    <message>
        <source>Delete the selected cam</source>
        <translation>Den gewählten Nocken löschen</translation>
    </message>
    <message>
        <source>Copy &amp;Output To…</source>
        <translation>&amp;Ausgang kopieren nach…</translation>
    </message>
    <message>
        <source>Copy the cams of the selected output to another output</source>
        <translation>Die Nocken des gewählten Ausgangs auf einen anderen Ausgang kopieren</translation>
    </message>
    <message>
        <source>Copy &amp;Program To…</source>
        <translation>&amp;Programm kopieren nach…</translation>
    </message>
    <message>
        <source>Copy the whole program to another program number</source>
        <translation>Das ganze Programm auf eine andere Programmnummer kopieren</translation>
    </message>
    <message>
        <source>&amp;Generate Cams…</source>
        <translation>Nocken &amp;erzeugen…</translation>
    </message>
    <message>
        <source>Replace the cams of the selected output by evenly spaced cams</source>
        <translation>Die Nocken des gewählten Ausgangs durch gleichmäßig verteilte Nocken ersetzen</translation>
    </message>
    <message>
        <source>&amp;Import CSV…</source>
        <translation>CSV &amp;importieren…</translation>
    </message>
    <message>
        <source>Replace the cams of this program from a CSV file</source>
        <translation>Die Nocken dieses Programms aus einer CSV-Datei ersetzen</translation>
    </message>
    <message>
        <source>&amp;Export CSV…</source>
        <translation>CSV e&amp;xportieren…</translation>
    </message>
    <message>
        <source>Save the cams of this program as a CSV file</source>
        <translation>Die Nocken dieses Programms als CSV-Datei speichern</translation>
    </message>
    <message>
        <source>Zoom &amp;In</source>
        <translation>Ver&amp;größern</translation>
    </message>
    <message>
        <source>Show a smaller part of the axis</source>
        <translation>Einen kleineren Teil der Achse zeigen</translation>
    </message>
    <message>
        <source>Zoom &amp;Out</source>
        <translation>Ver&amp;kleinern</translation>
    </message>
    <message>
        <source>Show a larger part of the axis</source>
        <translation>Einen größeren Teil der Achse zeigen</translation>
    </message>
    <message>
        <source>&amp;Fit</source>
        <translation>&amp;Einpassen</translation>
    </message>
    <message>
        <source>Show the whole axis IMIN..IMAX</source>
        <translation>Die ganze Achse IMIN..IMAX zeigen</translation>
    </message>
    <message>
        <source>no name</source>
        <translation>kein Name</translation>
    </message>
    <message>
        <source>&amp;Program:</source>
        <translation>&amp;Programm:</translation>
    </message>
    <message>
        <source>&amp;Name:</source>
        <translation>&amp;Name:</translation>
    </message>
    <message>
        <source>Cams of output %1</source>
        <translation>Nocken von Ausgang %1</translation>
    </message>
    <message>
        <source>Cams of output %1 (%2)</source>
        <translation>Nocken von Ausgang %1 (%2)</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Program Name</source>
        <translation>Programmname</translation>
    </message>
    <message>
        <source>Copy Output</source>
        <translation>Ausgang kopieren</translation>
    </message>
    <message>
        <source>Copy the cams of output %1 to output (its cams are replaced):</source>
        <translation>Die Nocken von Ausgang %1 kopieren auf Ausgang (dessen Nocken werden ersetzt):</translation>
    </message>
    <message>
        <source>Copy Program</source>
        <translation>Programm kopieren</translation>
    </message>
    <message>
        <source>Copy program %1 to program (its cams and name are replaced):</source>
        <translation>Programm %1 kopieren auf Programm (dessen Nocken und Name werden ersetzt):</translation>
    </message>
    <message>
        <source>%1: output %2 does not exist; the device has outputs 1..%3. Nothing was imported.</source>
        <translation>%1: Ausgang %2 gibt es nicht; das Gerät hat die Ausgänge 1..%3. Es wurde nichts importiert.</translation>
    </message>
    <message>
        <source>Import cams from %1</source>
        <translation>Nocken aus %1 importieren</translation>
    </message>
    <message>
        <source>Import Cams</source>
        <translation>Nocken importieren</translation>
    </message>
    <message>
        <source>CSV files (*.csv);;All files (*)</source>
        <translation>CSV-Dateien (*.csv);;Alle Dateien (*)</translation>
    </message>
    <message numerus="yes">
        <source>The cams were imported, but %n need fixing before they can be written (shown in red):
%1</source>
        <translation><numerusform>Die Nocken wurden importiert, aber %n muss korrigiert werden, bevor sie geschrieben werden können (rot markiert):
%1</numerusform><numerusform>Die Nocken wurden importiert, aber %n müssen korrigiert werden, bevor sie geschrieben werden können (rot markiert):
%1</numerusform></translation>
    </message>
    <message>
        <source>Export Cams</source>
        <translation>Nocken exportieren</translation>
    </message>
    <message>
        <source>program-%1.csv</source>
        <translation>programm-%1.csv</translation>
    </message>
</context>
<context>
    <name>cambench::CamGeneratorDialog</name>
    <message>
        <source>Fixed &amp;length and pitch</source>
        <translation>Feste &amp;Länge und Abstand</translation>
    </message>
    <message>
        <source>&amp;Number of cams and duty cycle</source>
        <translation>&amp;Anzahl der Nocken und Tastverhältnis</translation>
    </message>
    <message>
        <source>Generate Cams for Output %1</source>
        <translation>Nocken für Ausgang %1 erzeugen</translation>
    </message>
    <message>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <source>&amp;Start position:</source>
        <translation>&amp;Startposition:</translation>
    </message>
    <message>
        <source>Cam l&amp;ength:</source>
        <translation>Nocken&amp;länge:</translation>
    </message>
    <message>
        <source>&amp;Pitch:</source>
        <translation>&amp;Abstand:</translation>
    </message>
    <message>
        <source>&amp;Count:</source>
        <translation>An&amp;zahl:</translation>
    </message>
    <message>
        <source>&amp;Duty cycle:</source>
        <translation>&amp;Tastverhältnis:</translation>
    </message>
    <message>
        <source>The cams replace all cams of output %1.</source>
        <translation>Die Nocken ersetzen alle Nocken von Ausgang %1.</translation>
    </message>
    <message>
        <source>%1–%2</source>
        <translation>%1–%2</translation>
    </message>
    <message>
        <source>…</source>
        <translation>…</translation>
    </message>
    <message numerus="yes">
        <source>%n cam(s): %1</source>
        <translation><numerusform>%n Nocken: %1</numerusform><numerusform>%n Nocken: %1</numerusform></translation>
    </message>
    <message>
        <source>, </source>
        <translation>, </translation>
    </message>
</context>
<context>
    <name>cambench::CamPage</name>
    <message>
        <source>no cams</source>
        <translation>keine Nocken</translation>
    </message>
    <message>
        <source>Read program %1</source>
        <translation>Programm %1 lesen</translation>
    </message>
    <message>
        <source>Write program %1</source>
        <translation>Programm %1 schreiben</translation>
    </message>
    <message>
        <source>Reading program %1…</source>
        <translation>Programm %1 wird gelesen…</translation>
    </message>
    <message>
        <source>Program %1 not read: %2 Your edits are kept.</source>
        <translation>Programm %1 nicht gelesen: %2 Ihre Änderungen bleiben erhalten.</translation>
    </message>
    <message>
        <source>Program %1 read.</source>
        <translation>Programm %1 gelesen.</translation>
    </message>
    <message>
        <source>Program %1: %2</source>
        <translation>Programm %1: %2</translation>
    </message>
    <message>
        <source>Program %1, output %2</source>
        <translation>Programm %1, Ausgang %2</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>nicht gelesen</translation>
    </message>
    <message>
        <source>Program %1 name</source>
        <translation>Name von Programm %1</translation>
    </message>
    <message>
        <source>(other name)</source>
        <translation>(anderer Name)</translation>
    </message>
    <message>
        <source>Write cams</source>
        <translation>Nocken schreiben</translation>
    </message>
    <message>
        <source>Cam programs</source>
        <translation>Nockenprogramme</translation>
    </message>
</context>
<context>
    <name>cambench::CamTableModel</name>
    <message>
        <source>On</source>
        <translation>Ein</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Länge</translation>
    </message>
</context>
<context>
    <name>cambench::CommissioningReport</name>
    <message>
        <source>Commissioning report</source>
        <translation>Inbetriebnahmeprotokoll</translation>
    </message>
    <message>
        <source>Created %1 with CamBench %2</source>
        <translation>Erstellt am %1 mit CamBench %2</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>Firmware (EPROM date)</source>
        <translation>Firmware (EPROM-Datum)</translation>
    </message>
    <message>
        <source>Device number</source>
        <translation>Gerätenummer</translation>
    </message>
    <message>
        <source>Source</source>
        <translation>Quelle</translation>
    </message>
    <message>
        <source>offline project, not read from a device</source>
        <translation>Offline-Projekt, nicht aus einem Gerät gelesen</translation>
    </message>
    <message>
        <source>Outputs / inputs</source>
        <translation>Ausgänge / Eingänge</translation>
    </message>
    <message>
        <source>Programs</source>
        <translation>Programme</translation>
    </message>
    <message>
        <source>Position range</source>
        <translation>Positionsbereich</translation>
    </message>
    <message>
        <source>Settings</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>Settings not read.</source>
        <translation>Einstellungen nicht gelesen.</translation>
    </message>
    <message>
        <source>Outputs and dead times</source>
        <translation>Ausgänge und Totzeiten</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Ausgang</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Dead time</source>
        <translation>Totzeit</translation>
    </message>
    <message>
        <source>Program %1</source>
        <translation>Programm %1</translation>
    </message>
    <message>
        <source>Program %1: %2</source>
        <translation>Programm %1: %2</translation>
    </message>
    <message>
        <source>Switch on</source>
        <translation>Einschalten</translation>
    </message>
    <message>
        <source>Switch off</source>
        <translation>Ausschalten</translation>
    </message>
    <message>
        <source>Cannot write the report to %1: %2</source>
        <translation>Das Protokoll kann nicht nach %1 geschrieben werden: %2</translation>
    </message>
</context>
<context>
    <name>cambench::CompareDialog</name>
    <message>
        <source>Compare with device</source>
        <translation>Mit Gerät vergleichen</translation>
    </message>
    <message>
        <source>Item</source>
        <translation>Eintrag</translation>
    </message>
    <message>
        <source>On the device</source>
        <translation>Im Gerät</translation>
    </message>
    <message>
        <source>Edited on this PC</source>
        <translation>Auf diesem PC bearbeitet</translation>
    </message>
    <message>
        <source>Write selected</source>
        <translation>Auswahl schreiben</translation>
    </message>
    <message>
        <source>Write all</source>
        <translation>Alle schreiben</translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation>Aktualisieren</translation>
    </message>
    <message>
        <source>Items edited on this PC that differ from the device. Check the ones to write, or write all.</source>
        <translation>Auf diesem PC bearbeitete Einträge, die vom Gerät abweichen. Haken Sie die zu schreibenden an oder schreiben Sie alle.</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>No differences: the device holds what you see.</source>
        <translation>Keine Unterschiede: das Gerät enthält, was Sie sehen.</translation>
    </message>
    <message>
        <source>Nothing selected: nothing was written.</source>
        <translation>Nichts ausgewählt: es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>Writing…</source>
        <translation>Schreibt…</translation>
    </message>
</context>
<context>
    <name>cambench::ConnectionPage</name>
    <message>
        <source>Line</source>
        <translation>Leitung</translation>
    </message>
    <message>
        <source>A serial port, tcp://host:port for a serial device server, or the simulated device.</source>
        <translation>Eine serielle Schnittstelle, tcp://host:port für einen seriellen Geräteserver oder das simulierte Gerät.</translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation>Aktualisieren</translation>
    </message>
    <message>
        <source>Look for serial ports again</source>
        <translation>Erneut nach seriellen Schnittstellen suchen</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation>Schnittstelle:</translation>
    </message>
    <message>
        <source>Standard (point to point)</source>
        <translation>Standard (Punkt zu Punkt)</translation>
    </message>
    <message>
        <source>Multiuser (RS485 bus)</source>
        <translation>Multiuser (RS485-Bus)</translation>
    </message>
    <message>
        <source>Protocol:</source>
        <translation>Protokoll:</translation>
    </message>
    <message>
        <source>Baud rate:</source>
        <translation>Baudrate:</translation>
    </message>
    <message>
        <source>Multiuser: the number of the CamCon to talk to (0–63).</source>
        <translation>Multiuser: die Nummer der CamCon, mit der gesprochen wird (0–63).</translation>
    </message>
    <message>
        <source>Device number:</source>
        <translation>Gerätenummer:</translation>
    </message>
    <message>
        <source>Multiuser: this PC's own number on the bus (0–63).</source>
        <translation>Multiuser: die eigene Nummer dieses PCs auf dem Bus (0–63).</translation>
    </message>
    <message>
        <source>PC number:</source>
        <translation>PC-Nummer:</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Verbinden</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>Trennen</translation>
    </message>
    <message>
        <source>Devices on the line</source>
        <translation>Geräte an der Leitung</translation>
    </message>
    <message>
        <source>Scan bus</source>
        <translation>Bus absuchen</translation>
    </message>
    <message>
        <source>Ask every device number 0–63 for an answer (Multiuser), or identify the one device of a point-to-point line.</source>
        <translation>Jede Gerätenummer 0–63 nach einer Antwort fragen (Multiuser) oder das eine Gerät einer Punkt-zu-Punkt-Leitung erkennen.</translation>
    </message>
    <message>
        <source>Double-click a device to work with it.</source>
        <translation>Doppelklicken Sie ein Gerät, um damit zu arbeiten.</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>Simulated device</source>
        <translation>Simuliertes Gerät</translation>
    </message>
    <message>
        <source>Reconnect</source>
        <translation>Neu verbinden</translation>
    </message>
    <message>
        <source>Scanning the bus…</source>
        <translation>Bus wird abgesucht…</translation>
    </message>
    <message>
        <source>Identify device</source>
        <translation>Gerät erkennen</translation>
    </message>
    <message>
        <source>Bus scan failed: %1</source>
        <translation>Bussuche fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>CamCon, device number %1</source>
        <translation>CamCon, Gerätenummer %1</translation>
    </message>
    <message numerus="yes">
        <source>%n device(s) found</source>
        <translation><numerusform>%n Gerät gefunden</numerusform><numerusform>%n Geräte gefunden</numerusform></translation>
    </message>
    <message>
        <source>Not read from a device (offline project).</source>
        <translation>Nicht aus einem Gerät gelesen (Offline-Projekt).</translation>
    </message>
    <message>
        <source>%1 … %2</source>
        <translation>%1 … %2</translation>
    </message>
    <message>
        <source>Firmware (EPROM date):</source>
        <translation>Firmware (EPROM-Datum):</translation>
    </message>
    <message>
        <source>Outputs:</source>
        <translation>Ausgänge:</translation>
    </message>
    <message>
        <source>Inputs:</source>
        <translation>Eingänge:</translation>
    </message>
    <message>
        <source>Programs:</source>
        <translation>Programme:</translation>
    </message>
    <message>
        <source>0 … %1</source>
        <translation>0 … %1</translation>
    </message>
    <message>
        <source>Position range:</source>
        <translation>Positionsbereich:</translation>
    </message>
    <message>
        <source>Outputs with dead time:</source>
        <translation>Ausgänge mit Totzeit:</translation>
    </message>
    <message>
        <source>Maximum dead time:</source>
        <translation>Größte Totzeit:</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>Programmed cams:</source>
        <translation>Programmierte Nocken:</translation>
    </message>
    <message>
        <source>Free cam memory:</source>
        <translation>Freier Nockenspeicher:</translation>
    </message>
    <message numerus="yes">
        <source>%n cam(s)</source>
        <translation><numerusform>%n Nocken</numerusform><numerusform>%n Nocken</numerusform></translation>
    </message>
    <message>
        <source>CPU clock:</source>
        <translation>CPU-Takt:</translation>
    </message>
    <message>
        <source>25.2 MHz</source>
        <translation>25,2 MHz</translation>
    </message>
    <message>
        <source>16.7 MHz</source>
        <translation>16,7 MHz</translation>
    </message>
    <message>
        <source>Temperature:</source>
        <translation>Temperatur:</translation>
    </message>
    <message>
        <source>no sensor</source>
        <translation>kein Sensor</translation>
    </message>
    <message>
        <source>%1 °C</source>
        <translation>%1 °C</translation>
    </message>
    <message>
        <source>Connection</source>
        <translation>Verbindung</translation>
    </message>
</context>
<context>
    <name>cambench::DeadTimesModel</name>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>nicht gelesen</translation>
    </message>
    <message>
        <source>Edited, not yet written to the device.</source>
        <translation>Bearbeitet, noch nicht ins Gerät geschrieben.</translation>
    </message>
    <message>
        <source>Same as on the device.</source>
        <translation>Wie im Gerät.</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Ausgang</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Dead time</source>
        <translation>Totzeit</translation>
    </message>
    <message>
        <source>On the device</source>
        <translation>Im Gerät</translation>
    </message>
</context>
<context>
    <name>cambench::DeadTimesPage</name>
    <message>
        <source>Read from device</source>
        <translation>Aus Gerät lesen</translation>
    </message>
    <message>
        <source>Write changes</source>
        <translation>Änderungen schreiben</translation>
    </message>
    <message>
        <source>The dead time makes an output switch earlier by the time its actuator needs, at every speed. It belongs to the output, not to a program.</source>
        <translation>Die Totzeit lässt einen Ausgang um die Zeit früher schalten, die sein Stellglied braucht, bei jeder Geschwindigkeit. Sie gehört zum Ausgang, nicht zu einem Programm.</translation>
    </message>
    <message>
        <source>Dead times: %1</source>
        <translation>Totzeiten: %1</translation>
    </message>
    <message>
        <source>Dead times</source>
        <translation>Totzeiten</translation>
    </message>
    <message>
        <source>0.1 ms steps, at most %1 (?GTZKMAX)</source>
        <translation>Schritte von 0,1 ms, höchstens %1 (?GTZKMAX)</translation>
    </message>
    <message>
        <source>Reading dead times…</source>
        <translation>Totzeiten werden gelesen…</translation>
    </message>
    <message>
        <source>Read dead times</source>
        <translation>Totzeiten lesen</translation>
    </message>
    <message>
        <source>Reading dead times failed: %1</source>
        <translation>Lesen der Totzeiten fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Dead times read.</source>
        <translation>Totzeiten gelesen.</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>nicht gelesen</translation>
    </message>
    <message>
        <source>Output %1 dead time</source>
        <translation>Totzeit von Ausgang %1</translation>
    </message>
    <message>
        <source>Output %1 name</source>
        <translation>Name von Ausgang %1</translation>
    </message>
    <message>
        <source>Write dead times</source>
        <translation>Totzeiten schreiben</translation>
    </message>
</context>
<context>
    <name>cambench::DeviceSession</name>
    <message>
        <source>Connection to %1 lost, retrying</source>
        <translation>Verbindung zu %1 verloren, neuer Versuch läuft</translation>
    </message>
    <message>
        <source>Offline</source>
        <translation>Offline</translation>
    </message>
    <message>
        <source>Connecting to %1…</source>
        <translation>Verbinde mit %1…</translation>
    </message>
    <message>
        <source>Connected to the simulated device</source>
        <translation>Mit dem simulierten Gerät verbunden</translation>
    </message>
    <message>
        <source>Connected to %1</source>
        <translation>Verbunden mit %1</translation>
    </message>
</context>
<context>
    <name>cambench::MainWindow</name>
    <message>
        <source>Reconnect now</source>
        <translation>Jetzt neu verbinden</translation>
    </message>
    <message>
        <source>Connection re-established. Your edits are unchanged.</source>
        <translation>Verbindung wiederhergestellt. Ihre Änderungen sind unverändert.</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;New project…</source>
        <translation>&amp;Neues Projekt…</translation>
    </message>
    <message>
        <source>&amp;Open project…</source>
        <translation>Projekt ö&amp;ffnen…</translation>
    </message>
    <message>
        <source>&amp;Save project</source>
        <translation>Projekt &amp;speichern</translation>
    </message>
    <message>
        <source>Save project &amp;as…</source>
        <translation>Projekt speichern &amp;unter…</translation>
    </message>
    <message>
        <source>Commissioning &amp;report (PDF)…</source>
        <translation>Inbetriebnahme&amp;protokoll (PDF)…</translation>
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
        <source>&amp;Device</source>
        <translation>&amp;Gerät</translation>
    </message>
    <message>
        <source>&amp;Connect</source>
        <translation>&amp;Verbinden</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>&amp;Trennen</translation>
    </message>
    <message>
        <source>&amp;Read everything</source>
        <translation>&amp;Alles lesen</translation>
    </message>
    <message>
        <source>Co&amp;mpare with device…</source>
        <translation>Mit Gerät &amp;vergleichen…</translation>
    </message>
    <message>
        <source>&amp;Backup and restore…</source>
        <translation>&amp;Sichern und Wiederherstellen…</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Dark palette</source>
        <translation>&amp;Dunkle Farben</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;About CamBench</source>
        <translation>&amp;Über CamBench</translation>
    </message>
    <message>
        <source>About CamBench</source>
        <translation>Über CamBench</translation>
    </message>
    <message>
        <source>&lt;b&gt;CamBench %1&lt;/b&gt;&lt;p&gt;Programming, monitoring and backup of Digitronic CamCon electronic cam controllers.&lt;/p&gt;</source>
        <translation>&lt;b&gt;CamBench %1&lt;/b&gt;&lt;p&gt;Programmieren, Beobachten und Sichern von elektronischen Nockenschaltwerken Digitronic CamCon.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>CamCon %1 (device %2)</source>
        <translation>CamCon %1 (Gerät %2)</translation>
    </message>
    <message>
        <source>offline project</source>
        <translation>Offline-Projekt</translation>
    </message>
    <message>
        <source>CamBench – %1</source>
        <translation>CamBench – %1</translation>
    </message>
    <message numerus="yes">
        <source>[%n change(s) not written]</source>
        <translation><numerusform>[%n Änderung nicht geschrieben]</numerusform><numerusform>[%n Änderungen nicht geschrieben]</numerusform></translation>
    </message>
    <message>
        <source>The connection to %1 was lost: %2 CamBench retries by itself; your edits are kept.</source>
        <translation>Die Verbindung zu %1 ist verloren: %2 CamBench versucht es selbst erneut; Ihre Änderungen bleiben erhalten.</translation>
    </message>
    <message>
        <source>Connection lost: %1</source>
        <translation>Verbindung verloren: %1</translation>
    </message>
    <message>
        <source>Not connected: %1</source>
        <translation>Nicht verbunden: %1</translation>
    </message>
    <message>
        <source>Reading the device…</source>
        <translation>Gerät wird gelesen…</translation>
    </message>
    <message>
        <source>Read device identity</source>
        <translation>Gerätekennung lesen</translation>
    </message>
    <message>
        <source>The device did not identify itself: %1</source>
        <translation>Das Gerät hat sich nicht gemeldet: %1</translation>
    </message>
    <message>
        <source>Write: %1</source>
        <translation>Schreiben: %1</translation>
    </message>
    <message>
        <source>Unwritten changes</source>
        <translation>Nicht geschriebene Änderungen</translation>
    </message>
    <message numerus="yes">
        <source>%n change(s) are not written to the device. Close anyway?</source>
        <translation><numerusform>%n Änderung ist nicht ins Gerät geschrieben. Trotzdem schließen?</numerusform><numerusform>%n Änderungen sind nicht ins Gerät geschrieben. Trotzdem schließen?</numerusform></translation>
    </message>
    <message>
        <source>Compare with device…</source>
        <translation>Mit Gerät vergleichen…</translation>
    </message>
    <message>
        <source>Save project…</source>
        <translation>Projekt speichern…</translation>
    </message>
    <message>
        <source>Close without writing</source>
        <translation>Schließen ohne zu schreiben</translation>
    </message>
    <message>
        <source>New project</source>
        <translation>Neues Projekt</translation>
    </message>
    <message>
        <source>The current edits are not written or saved. Replace them?</source>
        <translation>Die aktuellen Änderungen sind weder geschrieben noch gespeichert. Ersetzen?</translation>
    </message>
    <message>
        <source>Open project</source>
        <translation>Projekt öffnen</translation>
    </message>
    <message>
        <source>CamBench projects (*.json)</source>
        <translation>CamBench-Projekte (*.json)</translation>
    </message>
    <message>
        <source>Project %1 opened. Its content is not on the device until you write it.</source>
        <translation>Projekt %1 geöffnet. Sein Inhalt ist erst im Gerät, wenn Sie ihn schreiben.</translation>
    </message>
    <message>
        <source>Save project</source>
        <translation>Projekt speichern</translation>
    </message>
    <message>
        <source>Project saved to %1.</source>
        <translation>Projekt nach %1 gespeichert.</translation>
    </message>
    <message>
        <source>Commissioning report</source>
        <translation>Inbetriebnahmeprotokoll</translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation>PDF-Dateien (*.pdf)</translation>
    </message>
    <message>
        <source>Report written to %1.</source>
        <translation>Protokoll nach %1 geschrieben.</translation>
    </message>
</context>
<context>
    <name>cambench::MonitorPage</name>
    <message>
        <source>Monitor</source>
        <translation>Beobachten</translation>
    </message>
    <message>
        <source>Reset error</source>
        <translation>Fehler zurücksetzen</translation>
    </message>
    <message>
        <source>Pause trend</source>
        <translation>Verlauf anhalten</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Achse</translation>
    </message>
    <message>
        <source>Position:</source>
        <translation>Position:</translation>
    </message>
    <message>
        <source>Speed:</source>
        <translation>Geschwindigkeit:</translation>
    </message>
    <message>
        <source>Active program:</source>
        <translation>Aktives Programm:</translation>
    </message>
    <message>
        <source>Activate</source>
        <translation>Aktivieren</translation>
    </message>
    <message>
        <source>Make this program the active one on the device.</source>
        <translation>Dieses Programm im Gerät aktiv schalten.</translation>
    </message>
    <message>
        <source>Switch to program:</source>
        <translation>Umschalten auf Programm:</translation>
    </message>
    <message>
        <source>State:</source>
        <translation>Zustand:</translation>
    </message>
    <message>
        <source>Outputs and inputs</source>
        <translation>Ausgänge und Eingänge</translation>
    </message>
    <message>
        <source>Outputs</source>
        <translation>Ausgänge</translation>
    </message>
    <message>
        <source>Inputs</source>
        <translation>Eingänge</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>How often the device is asked for its state.</source>
        <translation>Wie oft das Gerät nach seinem Zustand gefragt wird.</translation>
    </message>
    <message>
        <source>Poll every</source>
        <translation>Abfrage alle</translation>
    </message>
    <message>
        <source>Select program</source>
        <translation>Programm wählen</translation>
    </message>
    <message>
        <source>Program %1 is active.</source>
        <translation>Programm %1 ist aktiv.</translation>
    </message>
    <message>
        <source>Program %1 not activated: %2</source>
        <translation>Programm %1 nicht aktiviert: %2</translation>
    </message>
    <message>
        <source>Error reset sent.</source>
        <translation>Fehlerrücksetzung gesendet.</translation>
    </message>
    <message>
        <source>Error not reset: %1</source>
        <translation>Fehler nicht zurückgesetzt: %1</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Actual-value error %1: check the encoder and its cable, then reset.</source>
        <translation>Istwertfehler %1: Geber und Kabel prüfen, dann zurücksetzen.</translation>
    </message>
    <message>
        <source>Output error: an output is overloaded or short-circuited; fix it, then reset.</source>
        <translation>Ausgangsfehler: ein Ausgang ist überlastet oder kurzgeschlossen; beheben, dann zurücksetzen.</translation>
    </message>
    <message>
        <source>EEPROM checksum error: the stored data are damaged; restore a backup.</source>
        <translation>EEPROM-Prüfsummenfehler: die gespeicherten Daten sind beschädigt; stellen Sie eine Sicherung wieder her.</translation>
    </message>
    <message>
        <source>Unknown error state %1</source>
        <translation>Unbekannter Fehlerzustand %1</translation>
    </message>
    <message>
        <source>offline</source>
        <translation>offline</translation>
    </message>
</context>
<context>
    <name>cambench::NewProjectDialog</name>
    <message>
        <source>New project</source>
        <translation>Neues Projekt</translation>
    </message>
    <message>
        <source>Outputs (multiple of 8):</source>
        <translation>Ausgänge (Vielfaches von 8):</translation>
    </message>
    <message>
        <source>Inputs (multiple of 8):</source>
        <translation>Eingänge (Vielfaches von 8):</translation>
    </message>
    <message>
        <source>Programs:</source>
        <translation>Programme:</translation>
    </message>
    <message>
        <source>Smallest position (IMIN):</source>
        <translation>Kleinste Position (IMIN):</translation>
    </message>
    <message>
        <source>Largest position (IMAX):</source>
        <translation>Größte Position (IMAX):</translation>
    </message>
    <message>
        <source>Outputs with dead time:</source>
        <translation>Ausgänge mit Totzeit:</translation>
    </message>
</context>
<context>
    <name>cambench::PlcMatrixModel</name>
    <message>
        <source>Path %1, symbol %2: word %3 (provisional decoding: high byte operand kind, low byte number; enter 4 hex digits or e.g. M11)</source>
        <translation>Strompfad %1, Symbol %2: Wort %3 (vorläufige Deutung: High-Byte Operandenart, Low-Byte Nummer; 4 Hex-Ziffern oder z. B. M11 eingeben)</translation>
    </message>
    <message>
        <source>Symbol %1</source>
        <translation>Symbol %1</translation>
    </message>
    <message>
        <source>Path %1</source>
        <translation>Strompfad %1</translation>
    </message>
</context>
<context>
    <name>cambench::PlcPage</name>
    <message>
        <source>O – physical outputs</source>
        <translation>O – physikalische Ausgänge</translation>
    </message>
    <message>
        <source>P – cam controller inputs</source>
        <translation>P – Nockenschaltwerk-Eingänge</translation>
    </message>
    <message>
        <source>M – flags</source>
        <translation>M – Merker</translation>
    </message>
    <message>
        <source>X – X flags</source>
        <translation>X – X-Merker</translation>
    </message>
    <message>
        <source>Read network</source>
        <translation>Netzwerk lesen</translation>
    </message>
    <message>
        <source>Write changes</source>
        <translation>Änderungen schreiben</translation>
    </message>
    <message>
        <source>Area:</source>
        <translation>Bereich:</translation>
    </message>
    <message>
        <source>Number:</source>
        <translation>Nummer:</translation>
    </message>
    <message>
        <source>Preset of a timer or counter driving this output.</source>
        <translation>Vorgabewert eines Timers oder Zählers, der diesen Ausgang steuert.</translation>
    </message>
    <message>
        <source>Reset field for counters, 4 hex digits.</source>
        <translation>Resetfeld für Zähler, 4 Hex-Ziffern.</translation>
    </message>
    <message>
        <source>Network</source>
        <translation>Netzwerk</translation>
    </message>
    <message>
        <source>Value (timer/counter):</source>
        <translation>Wert (Timer/Zähler):</translation>
    </message>
    <message>
        <source>Reset field (hex):</source>
        <translation>Resetfeld (hex):</translation>
    </message>
    <message>
        <source>Symbols are decoded provisionally (high byte operand kind, low byte number; empty = 0000). Unknown words are shown as hex; every cell accepts 4 hex digits or a form like M11.</source>
        <translation>Symbole werden vorläufig gedeutet (High-Byte Operandenart, Low-Byte Nummer; leer = 0000). Unbekannte Wörter erscheinen hexadezimal; jede Zelle nimmt 4 Hex-Ziffern oder eine Form wie M11 an.</translation>
    </message>
    <message>
        <source>Networks read or edited in this session</source>
        <translation>In dieser Sitzung gelesene oder bearbeitete Netzwerke</translation>
    </message>
    <message>
        <source>PLC: %1</source>
        <translation>SPS: %1</translation>
    </message>
    <message>
        <source>Read PLC network</source>
        <translation>SPS-Netzwerk lesen</translation>
    </message>
    <message>
        <source>Reading %1 failed: %2</source>
        <translation>Lesen von %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>%1 read.</source>
        <translation>%1 gelesen.</translation>
    </message>
    <message>
        <source>Network %1</source>
        <translation>Netzwerk %1</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>nicht gelesen</translation>
    </message>
    <message>
        <source>Write PLC networks</source>
        <translation>SPS-Netzwerke schreiben</translation>
    </message>
    <message>
        <source>PLC</source>
        <translation>SPS</translation>
    </message>
</context>
<context>
    <name>cambench::ProgressPage</name>
    <message>
        <source>about %1 min %2 s left</source>
        <translation>noch etwa %1 min %2 s</translation>
    </message>
    <message>
        <source>about %1 s left</source>
        <translation>noch etwa %1 s</translation>
    </message>
</context>
<context>
    <name>cambench::SettingField</name>
    <message>
        <source>%1 … %2%3, steps of %4</source>
        <translation>%1 … %2%3, in Schritten von %4</translation>
    </message>
    <message>
        <source>%1 … %2%3</source>
        <translation>%1 … %2%3</translation>
    </message>
    <message>
        <source>output 1 … %1, 0 = none</source>
        <translation>Ausgang 1 … %1, 0 = keiner</translation>
    </message>
    <message>
        <source>input 1 … %1, 0 = none</source>
        <translation>Eingang 1 … %1, 0 = keiner</translation>
    </message>
    <message numerus="yes">
        <source>up to %n character(s)</source>
        <translation><numerusform>bis zu %n Zeichen</numerusform><numerusform>bis zu %n Zeichen</numerusform></translation>
    </message>
    <message>
        <source>Range: %1</source>
        <translation>Bereich: %1</translation>
    </message>
    <message>
        <source>Manual section %1</source>
        <translation>Handbuch Abschnitt %1</translation>
    </message>
    <message>
        <source>Read only: shown as the device reports it.</source>
        <translation>Nur lesbar: so angezeigt, wie das Gerät es meldet.</translation>
    </message>
    <message>
        <source>(not set)</source>
        <translation>(nicht gesetzt)</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keiner</translation>
    </message>
    <message>
        <source>unknown (%1)</source>
        <translation>unbekannt (%1)</translation>
    </message>
    <message>
        <source>On the device: %1</source>
        <translation>Im Gerät: %1</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>nicht gelesen</translation>
    </message>
</context>
<context>
    <name>cambench::SettingsPage</name>
    <message>
        <source>SSI encoder</source>
        <translation>SSI-Geber</translation>
    </message>
    <message>
        <source>Parallel encoder</source>
        <translation>Parallelgeber</translation>
    </message>
    <message>
        <source>Incremental encoder</source>
        <translation>Inkrementalgeber</translation>
    </message>
    <message>
        <source>Multi-turn encoder</source>
        <translation>Multiturn-Geber</translation>
    </message>
    <message>
        <source>PLL (pulse multiplier)</source>
        <translation>PLL (Impulsvervielfacher)</translation>
    </message>
    <message>
        <source>Time-based axis</source>
        <translation>Zeitbasierte Achse</translation>
    </message>
    <message>
        <source>Encoder</source>
        <translation>Geber</translation>
    </message>
    <message>
        <source>Actual-value adaptation</source>
        <translation>Istwertanpassung</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>Cycle and timing</source>
        <translation>Zyklus und Zeiten</translation>
    </message>
    <message>
        <source>Special outputs</source>
        <translation>Sonderausgänge</translation>
    </message>
    <message>
        <source>Device configuration</source>
        <translation>Gerätekonfiguration</translation>
    </message>
    <message>
        <source>PLC configuration</source>
        <translation>SPS-Konfiguration</translation>
    </message>
    <message>
        <source>Special encoder</source>
        <translation>Sondergeber</translation>
    </message>
    <message>
        <source>Analogue outputs</source>
        <translation>Analogausgänge</translation>
    </message>
    <message>
        <source>Program selection</source>
        <translation>Programmwahl</translation>
    </message>
    <message>
        <source>Display</source>
        <translation>Anzeige</translation>
    </message>
    <message>
        <source>Interface</source>
        <translation>Schnittstelle</translation>
    </message>
    <message>
        <source>Identity</source>
        <translation>Kennung</translation>
    </message>
    <message>
        <source>Expansion modules</source>
        <translation>Erweiterungsmodule</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Sprache</translation>
    </message>
    <message>
        <source>Read from device</source>
        <translation>Aus Gerät lesen</translation>
    </message>
    <message>
        <source>Write changes</source>
        <translation>Änderungen schreiben</translation>
    </message>
    <message>
        <source>Settings: %1</source>
        <translation>Einstellungen: %1</translation>
    </message>
    <message>
        <source>Reading settings…</source>
        <translation>Einstellungen werden gelesen…</translation>
    </message>
    <message>
        <source>Read settings</source>
        <translation>Einstellungen lesen</translation>
    </message>
    <message>
        <source>Reading settings failed: %1</source>
        <translation>Lesen der Einstellungen fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Settings read.</source>
        <translation>Einstellungen gelesen.</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>nicht gelesen</translation>
    </message>
    <message>
        <source>Setting %1</source>
        <translation>Einstellung %1</translation>
    </message>
    <message>
        <source>Write settings</source>
        <translation>Einstellungen schreiben</translation>
    </message>
    <message>
        <source>Encoder &amp; system</source>
        <translation>Geber &amp; System</translation>
    </message>
</context>
<context>
    <name>cambench::TerminalPage</name>
    <message>
        <source>Follow</source>
        <translation>Mitlaufen</translation>
    </message>
    <message>
        <source>e.g. ?IFGWG or ?NF000003 — checksum and CR LF are added</source>
        <translation>z. B. ?IFGWG oder ?NF000003 — Prüfsumme und CR LF werden ergänzt</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>Senden</translation>
    </message>
    <message>
        <source>Command:</source>
        <translation>Befehl:</translation>
    </message>
    <message>
        <source>Save log…</source>
        <translation>Protokoll speichern…</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Leeren</translation>
    </message>
    <message>
        <source>Traffic (user numbers masked)</source>
        <translation>Datenverkehr (Benutzernummern verdeckt)</translation>
    </message>
    <message>
        <source>Save traffic log</source>
        <translation>Verkehrsprotokoll speichern</translation>
    </message>
    <message>
        <source>Text files (*.txt *.log)</source>
        <translation>Textdateien (*.txt *.log)</translation>
    </message>
    <message>
        <source>A command starts with ? (query) or ! (command), then its letters and data, e.g. ?IFGWG.</source>
        <translation>Ein Befehl beginnt mit ? (Frage) oder ! (Befehl), dann folgen seine Buchstaben und Daten, z. B. ?IFGWG.</translation>
    </message>
    <message>
        <source>Terminal</source>
        <translation>Terminal</translation>
    </message>
    <message>
        <source>&lt; error: %1</source>
        <translation>&lt; Fehler: %1</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
</context>
<context>
    <name>cambench::TrackTableModel</name>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>unchanged</source>
        <translation>unverändert</translation>
    </message>
    <message>
        <source>edited</source>
        <translation>bearbeitet</translation>
    </message>
    <message>
        <source>PC only</source>
        <translation>nur PC</translation>
    </message>
    <message>
        <source>Output %1 is the same as on the device.</source>
        <translation>Ausgang %1 ist wie im Gerät.</translation>
    </message>
    <message>
        <source>Output %1 was changed and is not yet written to the device.</source>
        <translation>Ausgang %1 wurde geändert und ist noch nicht ins Gerät geschrieben.</translation>
    </message>
    <message>
        <source>Program %1 was never read from the device; its cams exist only on this PC.</source>
        <translation>Programm %1 wurde nie aus dem Gerät gelesen; seine Nocken gibt es nur auf diesem PC.</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Ausgang</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Dead time</source>
        <translation>Totzeit</translation>
    </message>
    <message>
        <source>Cams</source>
        <translation>Nocken</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
</context>
<context>
    <name>cambench::TrendChart</name>
    <message>
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
</context>
<context>
    <name>cambench::UsersModel</name>
    <message>
        <source>program selection</source>
        <translation>Programmwahl</translation>
    </message>
    <message>
        <source>programming</source>
        <translation>Programmieren</translation>
    </message>
    <message>
        <source>system settings</source>
        <translation>Systemeinstellungen</translation>
    </message>
    <message>
        <source>configuration</source>
        <translation>Konfiguration</translation>
    </message>
    <message>
        <source>PLC</source>
        <translation>SPS</translation>
    </message>
    <message>
        <source>all outputs</source>
        <translation>alle Ausgänge</translation>
    </message>
    <message>
        <source>users</source>
        <translation>Benutzer</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keiner</translation>
    </message>
    <message>
        <source>Edited, not yet written to the device.</source>
        <translation>Bearbeitet, noch nicht ins Gerät geschrieben.</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>User number</source>
        <translation>Benutzernummer</translation>
    </message>
    <message>
        <source>Rights</source>
        <translation>Rechte</translation>
    </message>
</context>
<context>
    <name>cambench::UsersPage</name>
    <message>
        <source>Show numbers</source>
        <translation>Nummern zeigen</translation>
    </message>
    <message>
        <source>May change all outputs</source>
        <translation>Darf alle Ausgänge ändern</translation>
    </message>
    <message>
        <source>Read from device</source>
        <translation>Aus Gerät lesen</translation>
    </message>
    <message>
        <source>Write changes</source>
        <translation>Änderungen schreiben</translation>
    </message>
    <message>
        <source>Add user</source>
        <translation>Benutzer hinzufügen</translation>
    </message>
    <message>
        <source>Remove user</source>
        <translation>Benutzer entfernen</translation>
    </message>
    <message>
        <source>User numbers are access codes. They stay hidden unless you show them.</source>
        <translation>Benutzernummern sind Zugangscodes. Sie bleiben verborgen, bis Sie sie zeigen.</translation>
    </message>
    <message>
        <source>User</source>
        <translation>Benutzer</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>Name:</translation>
    </message>
    <message>
        <source>User number:</source>
        <translation>Benutzernummer:</translation>
    </message>
    <message>
        <source>Rights</source>
        <translation>Rechte</translation>
    </message>
    <message>
        <source>Program selection</source>
        <translation>Programmwahl</translation>
    </message>
    <message>
        <source>Programming</source>
        <translation>Programmieren</translation>
    </message>
    <message>
        <source>System settings</source>
        <translation>Systemeinstellungen</translation>
    </message>
    <message>
        <source>Device configuration</source>
        <translation>Gerätekonfiguration</translation>
    </message>
    <message>
        <source>PLC menu</source>
        <translation>SPS-Menü</translation>
    </message>
    <message>
        <source>All outputs menu</source>
        <translation>Menü alle Ausgänge</translation>
    </message>
    <message>
        <source>User menu</source>
        <translation>Benutzermenü</translation>
    </message>
    <message>
        <source>Outputs this user may change</source>
        <translation>Ausgänge, die dieser Benutzer ändern darf</translation>
    </message>
    <message>
        <source>Users: %1</source>
        <translation>Benutzer: %1</translation>
    </message>
    <message>
        <source>New user</source>
        <translation>Neuer Benutzer</translation>
    </message>
    <message>
        <source>hidden – check "Show numbers" to see or change it</source>
        <translation>verborgen – „Nummern zeigen“ anhaken, um sie zu sehen oder zu ändern</translation>
    </message>
    <message>
        <source>Reading users…</source>
        <translation>Benutzer werden gelesen…</translation>
    </message>
    <message>
        <source>Read users</source>
        <translation>Benutzer lesen</translation>
    </message>
    <message>
        <source>Reading users failed: %1</source>
        <translation>Lesen der Benutzer fehlgeschlagen: %1</translation>
    </message>
    <message numerus="yes">
        <source>%n user(s) read.</source>
        <translation><numerusform>%n Benutzer gelesen.</numerusform><numerusform>%n Benutzer gelesen.</numerusform></translation>
    </message>
    <message>
        <source>%1, number %2, rights: %3</source>
        <translation>%1, Nummer %2, Rechte: %3</translation>
    </message>
    <message>
        <source>absent</source>
        <translation>nicht vorhanden</translation>
    </message>
    <message>
        <source>User "%1"</source>
        <translation>Benutzer „%1“</translation>
    </message>
    <message>
        <source>deleted</source>
        <translation>gelöscht</translation>
    </message>
    <message>
        <source>The user has no number: enter one.</source>
        <translation>Der Benutzer hat keine Nummer: geben Sie eine ein.</translation>
    </message>
    <message>
        <source>Write users</source>
        <translation>Benutzer schreiben</translation>
    </message>
    <message>
        <source>Users</source>
        <translation>Benutzer</translation>
    </message>
</context>
</TS>
