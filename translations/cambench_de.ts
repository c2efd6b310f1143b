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
    <name>DeviceErrors</name>
    <message>
        <source>The device&apos;s RAM is too small for this setting (manual: &quot;RAM zu klein für Einstellung&quot;). Choose a smaller value, e.g. fewer PLC elements.</source>
        <translation>Der RAM des Geräts ist zu klein für diese Einstellung (Handbuch: „RAM zu klein für Einstellung“). Wählen Sie einen kleineren Wert, z. B. weniger SPS-Elemente.</translation>
    </message>
    <message>
        <source>The dead-time compensation value is too large. Enter at most the device&apos;s maximum dead time (cambench-cli info: maxDeadTime).</source>
        <translation>Der Wert der Totzeitkompensation ist zu groß. Geben Sie höchstens die maximale Totzeit des Geräts ein (cambench-cli info: maxDeadTime).</translation>
    </message>
    <message>
        <source>The device&apos;s EEPROM is defective. Back up what can still be read and have the device repaired.</source>
        <translation>Das EEPROM des Geräts ist defekt. Sichern Sie, was sich noch lesen lässt, und lassen Sie das Gerät reparieren.</translation>
    </message>
    <message>
        <source>The device&apos;s EEPROM is full. Delete cams or programs that are no longer needed, then write again.</source>
        <translation>Das EEPROM des Geräts ist voll. Löschen Sie nicht mehr benötigte Nocken oder Programme und schreiben Sie dann erneut.</translation>
    </message>
    <message>
        <source>Checksum error in the device&apos;s EEPROM: the stored data may be damaged. Restore a backup or enter the data again.</source>
        <translation>Prüfsummenfehler im EEPROM des Geräts: die gespeicherten Daten sind möglicherweise beschädigt. Stellen Sie eine Sicherung wieder her oder geben Sie die Daten neu ein.</translation>
    </message>
    <message>
        <source>Block 0000 of the restore (!EE) has the wrong length: the image does not suit this device. Use an image taken from this kind of device.</source>
        <translation>Block 0000 der Wiederherstellung (!EE) hat die falsche Länge: das Abbild passt nicht zu diesem Gerät. Verwenden Sie ein Abbild von einem Gerät dieser Art.</translation>
    </message>
    <message>
        <source>The device cannot erase its EEPROM. Switch it off and on and restore again; if that fails too, the device needs repair.</source>
        <translation>Das Gerät kann sein EEPROM nicht löschen. Schalten Sie es aus und wieder ein und stellen Sie erneut wieder her; schlägt auch das fehl, muss das Gerät repariert werden.</translation>
    </message>
    <message>
        <source>The restore (!EE) sent the blocks in the wrong block number order. Restore again from the start; if it happens again, the image file is damaged.</source>
        <translation>Die Wiederherstellung (!EE) hat die Blöcke in falscher Reihenfolge der Blocknummern gesendet. Stellen Sie von vorn wieder her; geschieht das erneut, ist die Abbilddatei beschädigt.</translation>
    </message>
    <message>
        <source>The CamCon cannot start after the restore (!EE): the data do not suit it. Restore the safety backup or an image taken from this device.</source>
        <translation>Die CamCon kann nach der Wiederherstellung (!EE) nicht starten: die Daten passen nicht zu ihr. Stellen Sie die Sicherheitskopie oder ein Abbild dieses Geräts wieder her.</translation>
    </message>
    <message>
        <source>A block of the restore (!EE) has the wrong length: the image file is damaged. Restore another image.</source>
        <translation>Ein Block der Wiederherstellung (!EE) hat die falsche Länge: die Abbilddatei ist beschädigt. Stellen Sie ein anderes Abbild wieder her.</translation>
    </message>
    <message>
        <source>The device did not receive the data completely: the line lost bytes. Check the cable and the baud rate, then try again.</source>
        <translation>Das Gerät hat die Daten nicht vollständig empfangen: auf der Leitung gingen Bytes verloren. Prüfen Sie Kabel und Baudrate und versuchen Sie es erneut.</translation>
    </message>
    <message>
        <source>The manual gives no meaning for error -1 (it lists it only as &quot;unknown error&quot;). The device refused the request: check that the values lie within its limits and that the item exists.</source>
        <translation>Das Handbuch nennt für Fehler -1 keine Bedeutung (es führt ihn nur als „unbekannter Fehler“). Das Gerät hat die Anfrage abgelehnt: prüfen Sie, ob die Werte in seinen Grenzen liegen und ob das Element existiert.</translation>
    </message>
    <message>
        <source>The manual gives no meaning for error %1. Note the number and the command and ask the device&apos;s supplier.</source>
        <translation>Das Handbuch nennt für Fehler %1 keine Bedeutung. Notieren Sie Nummer und Befehl und fragen Sie den Lieferanten des Geräts.</translation>
    </message>
</context>
<context>
    <name>PageWriteReport</name>
    <message numerus="yes">
        <source>%n edited value(s) on this page are not written. Replace them with what the device holds?</source>
        <translation>
            <numerusform>%n geänderter Wert auf dieser Seite ist nicht geschrieben. Durch die Werte im Gerät ersetzen?</numerusform>
            <numerusform>%n geänderte Werte auf dieser Seite sind nicht geschrieben. Durch die Werte im Gerät ersetzen?</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ReplacementQuestion</name>
    <message>
        <source>not recorded</source>
        <translation>nicht aufgezeichnet</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>%1: %2 (the same)</source>
        <translation>%1: %2 (gleich)</translation>
    </message>
    <message>
        <source>%1: backup %2, this device %3  ← differs</source>
        <translation>%1: Sicherung %2, dieses Gerät %3  ← weicht ab</translation>
    </message>
    <message>
        <source>The device answering is not the one %1 was taken from.</source>
        <translation>Das antwortende Gerät ist nicht das, von dem %1 stammt.</translation>
    </message>
    <message>
        <source>%1 records no identity of the device it was taken from (an older backup): CamBench cannot tell whether the device answering is that device.</source>
        <translation>%1 zeichnet keine Identität des Geräts auf, von dem es stammt (eine ältere Sicherung): CamBench kann nicht sagen, ob das antwortende Gerät dieses Gerät ist.</translation>
    </message>
    <message>
        <source>%1

Restore it here only if this device replaces the one the backup was taken from (or, for an older backup, is that device). Nothing has been written yet.</source>
        <translation>%1

Stellen Sie sie hier nur wieder her, wenn dieses Gerät das ersetzt, von dem die Sicherung stammt (oder, bei einer älteren Sicherung, dieses Gerät ist). Noch wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>It replaces that device: restore</source>
        <translation>Es ersetzt jenes Gerät: wiederherstellen</translation>
    </message>
    <message>
        <source>Check which device answers</source>
        <translation>Prüfen, welches Gerät antwortet</translation>
    </message>
    <message>
        <source>Nothing was written: which device answers could not be read: %1</source>
        <translation>Nichts wurde geschrieben: welches Gerät antwortet, ließ sich nicht lesen: %1</translation>
    </message>
</context>
<context>
    <name>Settings</name>
    <message>
        <source>Encoder</source>
        <translation>Geber</translation>
    </message>
    <message>
        <source>The position encoder connected to the device, from the device&apos;s list of encoders, or the programmable special encoder set up on the special encoder page.</source>
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
        <source>Input that receives the PLL&apos;s pulses.</source>
        <translation>Eingang, der die Impulse der PLL empfängt.</translation>
    </message>
    <message>
        <source>PLL clear input</source>
        <translation>PLL-Löscheingang</translation>
    </message>
    <message>
        <source>Input that clears the PLL&apos;s position (0 = none).</source>
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
        <source>Input that locks the device&apos;s keyboard (0 = none).</source>
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
        <source>Actual value at which a new program takes effect (mode &quot;At actual value&quot; only).</source>
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
        <source>Language of the device&apos;s display: 0 German, 1 English, 2 French; further numbers depend on the firmware.</source>
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
        <source>Switches the PLC module off or on; &quot;flags retained&quot; keeps the flags at power-off.</source>
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
    <name>TimingText</name>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>above %1</source>
        <translation>über %1</translation>
    </message>
    <message>
        <source>at every speed</source>
        <translation>bei jeder Geschwindigkeit</translation>
    </message>
    <message>
        <source>Output %1: cam %2 vanishes %3 (the switch-off dead time is longer than the switch-on one).</source>
        <translation>Ausgang %1: Nocke %2 verschwindet %3 (die Ausschalt-Totzeit ist länger als die Einschalt-Totzeit).</translation>
    </message>
    <message>
        <source>Output %1: cams %2 and %3 merge %4.</source>
        <translation>Ausgang %1: Nocken %2 und %3 verschmelzen %4.</translation>
    </message>
    <message>
        <source>Output %1: cam %2 is on for less than the minimum pulse %3.</source>
        <translation>Ausgang %1: Nocke %2 ist kürzer eingeschaltet als der Mindestimpuls %3.</translation>
    </message>
    <message>
        <source>Output %1: the switch points move by more than one cycle %2.</source>
        <translation>Ausgang %1: Die Schaltpunkte verschieben sich um mehr als einen Zyklus %2.</translation>
    </message>
</context>
<context>
    <name>cambench</name>
    <message>
        <source>On the device: %1</source>
        <translation>Im Gerät: %1</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
    <message>
        <source>%1: &quot;volatile&quot; holds an empty item; name items as a comparison names them (&quot;V12&quot;) or a range (&quot;V100-V199&quot;).</source>
        <translation>%1: &quot;volatile&quot; enthält ein leeres Element; nennen Sie Elemente so, wie ein Vergleich sie nennt (&quot;V12&quot;), oder als Bereich (&quot;V100-V199&quot;).</translation>
    </message>
    <message>
        <source>%1: the volatile range &quot;%2&quot; ends below its start; write it low to high.</source>
        <translation>%1: der flüchtige Bereich &quot;%2&quot; endet unter seinem Anfang; schreiben Sie ihn von niedrig nach hoch.</translation>
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
    <name>cambench::AnalogueCamsPage</name>
    <message>
        <source>Analogue cams</source>
        <translation>Analognocken</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <source>Analogue value</source>
        <translation>Analogwert</translation>
    </message>
    <message>
        <source>Between two base points the analogue output follows a straight line (with interpolation on). Positions must rise from point to point.</source>
        <translation>Zwischen zwei Stützpunkten folgt der Analogausgang einer Geraden (bei eingeschalteter Interpolation). Die Positionen müssen von Punkt zu Punkt steigen.</translation>
    </message>
    <message>
        <source>Add point</source>
        <translation>Punkt hinzufügen</translation>
    </message>
    <message>
        <source>Remove point</source>
        <translation>Punkt entfernen</translation>
    </message>
    <message>
        <source>Analogue output:</source>
        <translation>Analogausgang:</translation>
    </message>
    <message>
        <source>Read analogue cams</source>
        <translation>Analognocken lesen</translation>
    </message>
    <message>
        <source>Reading analogue cams failed: %1</source>
        <translation>Lesen der Analognocken fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Analogue cams of output %1 read.</source>
        <translation>Analognocken von Ausgang %1 gelesen.</translation>
    </message>
    <message>
        <source>no such point</source>
        <translation>kein solcher Punkt</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>nicht gelesen</translation>
    </message>
    <message>
        <source>Analogue output %1: not read from the device.</source>
        <translation>Analogausgang %1: nicht vom Gerät gelesen.</translation>
    </message>
    <message>
        <source>Analogue output %1: edited, not written. On the device: %2</source>
        <translation>Analogausgang %1: bearbeitet, nicht geschrieben. Auf dem Gerät: %2</translation>
    </message>
    <message>
        <source>Analogue output %1: as on the device.</source>
        <translation>Analogausgang %1: wie auf dem Gerät.</translation>
    </message>
    <message>
        <source>Analogue output %1</source>
        <translation>Analogausgang %1</translation>
    </message>
    <message>
        <source>this device has no analogue outputs, so it has no analogue cams</source>
        <translation>dieses Gerät hat keine Analogausgänge, also auch keine Analognocken</translation>
    </message>
    <message>
        <source>this device has analogue outputs 1..%1 only</source>
        <translation>dieses Gerät hat nur die Analogausgänge 1..%1</translation>
    </message>
</context>
<context>
    <name>cambench::BackupPage</name>
    <message>
        <source>Backup or restore…</source>
        <translation>Sichern oder wiederherstellen…</translation>
    </message>
    <message>
        <source>Backup</source>
        <translation>Sicherung</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Backup and restore&lt;/h3&gt;&lt;p&gt;A &lt;b&gt;backup&lt;/b&gt; copies the whole EEPROM of the device (cam programs, dead times, settings, users, PLC) block by block into a file.&lt;/p&gt;&lt;p&gt;A &lt;b&gt;restore&lt;/b&gt; erases the device and writes such a file back. CamBench checks the file first, restores it only to the device it was taken from (or to its replacement when you say so), and saves what the device holds now into a safety backup before it erases anything.&lt;/p&gt;&lt;p&gt;If a restore is interrupted, the device stays erased and does not run until an image is restored completely: keep the safety backup.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Sichern und Wiederherstellen&lt;/h3&gt;&lt;p&gt;Eine &lt;b&gt;Sicherung&lt;/b&gt; kopiert das ganze EEPROM des Geräts (Nockenprogramme, Totzeiten, Einstellungen, Benutzer, SPS) Block für Block in eine Datei.&lt;/p&gt;&lt;p&gt;Eine &lt;b&gt;Wiederherstellung&lt;/b&gt; löscht das Gerät und schreibt eine solche Datei zurück. CamBench prüft die Datei vorher, stellt sie nur auf dem Gerät wieder her, von dem sie stammt (oder auf Ihre Angabe hin auf seinem Ersatz), und sichert den jetzigen Inhalt des Geräts in eine Sicherheitskopie, bevor es etwas löscht.&lt;/p&gt;&lt;p&gt;Wird eine Wiederherstellung unterbrochen, bleibt das Gerät gelöscht und läuft nicht, bis ein Abbild vollständig wiederhergestellt ist: Bewahren Sie die Sicherheitskopie auf.&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>cambench::BackupProgramsView</name>
    <message>
        <source>Hide outputs without a difference</source>
        <translation>Ausgänge ohne Unterschied ausblenden</translation>
    </message>
    <message>
        <source>Program %1</source>
        <translation>Programm %1</translation>
    </message>
    <message>
        <source>Program %1 (%2)</source>
        <translation>Programm %1 (%2)</translation>
    </message>
    <message numerus="yes">
        <source>%n difference(s)</source>
        <translation>
            <numerusform>%n Unterschied</numerusform>
            <numerusform>%n Unterschiede</numerusform>
        </translation>
    </message>
    <message>
        <source>Programs that differ:</source>
        <translation>Programme mit Unterschieden:</translation>
    </message>
    <message numerus="yes">
        <source>A: %1, program %2. B: %3, program %2. %n difference(s) of cams.</source>
        <translation>
            <numerusform>A: %1, Programm %2. B: %3, Programm %2. %n Unterschied der Nocken.</numerusform>
            <numerusform>A: %1, Programm %2. B: %3, Programm %2. %n Unterschiede der Nocken.</numerusform>
        </translation>
    </message>
    <message>
        <source>Name &quot;%1&quot; → &quot;%2&quot;.</source>
        <translation>Name „%1“ → „%2“.</translation>
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
        <source>Choose where the safety backup goes.</source>
        <translation>Wählen Sie, wohin die Sicherheitskopie geschrieben wird.</translation>
    </message>
    <message numerus="yes">
        <source>Image: %1
Taken %2 with %3, %n block(s), %4 bytes.</source>
        <translation>
            <numerusform>Abbild: %1
Erstellt %2 mit %3, %n Block, %4 Bytes.</numerusform>
            <numerusform>Abbild: %1
Erstellt %2 mit %3, %n Blöcke, %4 Bytes.</numerusform>
        </translation>
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
    <message numerus="yes">
        <source>Backup complete: %n block(s), %1 bytes written to %2. Nothing failed.</source>
        <translation>
            <numerusform>Sicherung vollständig: %n Block, %1 Bytes nach %2 geschrieben. Nichts ist fehlgeschlagen.</numerusform>
            <numerusform>Sicherung vollständig: %n Blöcke, %1 Bytes nach %2 geschrieben. Nichts ist fehlgeschlagen.</numerusform>
        </translation>
    </message>
    <message>
        <source>Restore</source>
        <translation>Wiederherstellung</translation>
    </message>
    <message numerus="yes">
        <source>Restore complete: %n block(s) written, 0 failed. The safety backup of the previous content is %1.</source>
        <translation>
            <numerusform>Wiederherstellung vollständig: %n Block geschrieben, 0 fehlgeschlagen. Die Sicherheitskopie des vorherigen Inhalts ist %1.</numerusform>
            <numerusform>Wiederherstellung vollständig: %n Blöcke geschrieben, 0 fehlgeschlagen. Die Sicherheitskopie des vorherigen Inhalts ist %1.</numerusform>
        </translation>
    </message>
    <message>
        <source>Cancel the restore? If the device is already being written, it stays ERASED until you restore an image.</source>
        <translation>Wiederherstellung abbrechen? Wird das Gerät bereits beschrieben, bleibt es GELÖSCHT, bis Sie ein Abbild wiederherstellen.</translation>
    </message>
    <message>
        <source>Cancel the backup? No file will be written.</source>
        <translation>Sicherung abbrechen? Es wird keine Datei geschrieben.</translation>
    </message>
    <message>
        <source>This erases the device (%1) and writes the image %2 into it. Outputs may switch while the device restarts.

Erase and restore now?</source>
        <translation>Dies löscht das Gerät (%1) und schreibt das Abbild %2 hinein. Während das Gerät neu startet, können Ausgänge schalten.

Jetzt löschen und wiederherstellen?</translation>
    </message>
    <message>
        <source>Erase and restore</source>
        <translation>Löschen und wiederherstellen</translation>
    </message>
    <message numerus="yes">
        <source>Step 1 of 2: saving what the device holds now into %1; step 2: erasing the device and writing %n block(s).</source>
        <translation>
            <numerusform>Schritt 1 von 2: den jetzigen Inhalt des Geräts nach %1 sichern; Schritt 2: das Gerät löschen und %n Block schreiben.</numerusform>
            <numerusform>Schritt 1 von 2: den jetzigen Inhalt des Geräts nach %1 sichern; Schritt 2: das Gerät löschen und %n Blöcke schreiben.</numerusform>
        </translation>
    </message>
    <message>
        <source>Restore NOT done, the device is unchanged: %1</source>
        <translation>Wiederherstellung NICHT ausgeführt, das Gerät ist unverändert: %1</translation>
    </message>
    <message>
        <source>Restore FAILED: %1</source>
        <translation>Wiederherstellung FEHLGESCHLAGEN: %1</translation>
    </message>
    <message>
        <source>A backup copies the device&apos;s whole EEPROM into a file. A restore erases the device and writes such a file back. The file holds the users&apos; access codes: keep it where only you can read it.</source>
        <translation>Eine Sicherung kopiert das ganze EEPROM des Geräts in eine Datei. Eine Wiederherstellung löscht das Gerät und schreibt eine solche Datei zurück. Die Datei enthält die Zugangscodes der Benutzer: bewahren Sie sie so auf, dass nur Sie sie lesen können.</translation>
    </message>
</context>
<context>
    <name>cambench::CamBusView</name>
    <message>
        <source>&lt;b&gt;Cam-BUS&lt;/b&gt; as this PC hears it</source>
        <translation>&lt;b&gt;Cam-BUS&lt;/b&gt;, wie dieser PC ihn hört</translation>
    </message>
    <message>
        <source>Not on a Cam-BUS: connect with the Cam-BUS protocol to see its users and the token.</source>
        <translation>Nicht an einem Cam-BUS: mit dem Protokoll Cam-BUS verbinden, um seine Teilnehmer und das Token zu sehen.</translation>
    </message>
    <message>
        <source>Not live: nothing heard from the line for %1 s; the users below are the last ones heard.</source>
        <translation>Nicht aktuell: seit %1 s nichts von der Leitung gehört; unten die zuletzt gehörten Teilnehmer.</translation>
    </message>
    <message numerus="yes">
        <source>Initialisation phase: the master searches the users (%n found so far).</source>
        <translation>
            <numerusform>Initialisierungsphase: der Master sucht die Teilnehmer (bisher %n gefunden).</numerusform>
            <numerusform>Initialisierungsphase: der Master sucht die Teilnehmer (bisher %n gefunden).</numerusform>
        </translation>
    </message>
    <message>
        <source>Listening: no token heard yet.</source>
        <translation>Hört zu: noch kein Token gehört.</translation>
    </message>
    <message numerus="yes">
        <source>%n users · master %1 · token with %2 · %3 rounds/s</source>
        <translation>
            <numerusform>%n Teilnehmer · Master %1 · Token bei %2 · %3 Runden/s</numerusform>
            <numerusform>%n Teilnehmer · Master %1 · Token bei %2 · %3 Runden/s</numerusform>
        </translation>
    </message>
    <message>
        <source>Initialisation phases heard since connecting: %1</source>
        <translation>Initialisierungsphasen seit dem Verbinden: %1</translation>
    </message>
    <message>
        <source>User %1</source>
        <translation>Teilnehmer %1</translation>
    </message>
    <message>
        <source>master: passes the token</source>
        <translation>Master: gibt das Token weiter</translation>
    </message>
    <message>
        <source>this PC</source>
        <translation>dieser PC</translation>
    </message>
    <message>
        <source>does not answer (stays in the table until the next initialisation phase)</source>
        <translation>antwortet nicht (bleibt bis zur nächsten Initialisierungsphase in der Tabelle)</translation>
    </message>
</context>
<context>
    <name>cambench::CamConGui</name>
    <message>
        <source>CamCon %1, device number %2.</source>
        <translation>CamCon %1, Gerätenummer %2.</translation>
    </message>
    <message>
        <source>CamCon %1 (device %2)</source>
        <translation>CamCon %1 (Gerät %2)</translation>
    </message>
    <message>
        <source>offline project</source>
        <translation>Offline-Projekt</translation>
    </message>
</context>
<context>
    <name>cambench::CamConIdentityPanel</name>
    <message>
        <source>Not read from a device (offline project).</source>
        <translation>Nicht aus einem Gerät gelesen (Offline-Projekt).</translation>
    </message>
    <message>
        <source>Last connected: CamCon %1, device number %2, at %3. Not necessarily the device on the port chosen now.</source>
        <translation>Zuletzt verbunden: CamCon %1, Gerätenummer %2, um %3. Nicht unbedingt das Gerät an der jetzt gewählten Schnittstelle.</translation>
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
        <source>Device number:</source>
        <translation>Gerätenummer:</translation>
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
        <translation>
            <numerusform>%n Nocken</numerusform>
            <numerusform>%n Nocken</numerusform>
        </translation>
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
</context>
<context>
    <name>cambench::CamConSectionPage</name>
    <message>
        <source>%1: nothing to write, the device holds what you see.</source>
        <translation>%1: nichts zu schreiben, das Gerät enthält, was Sie sehen.</translation>
    </message>
    <message>
        <source>%1: writing…</source>
        <translation>%1: wird geschrieben…</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message numerus="yes">
        <source>%n other item(s) of this section were already as on the device and not sent.</source>
        <translation>
            <numerusform>%n weiteres Element dieses Bereichs war bereits wie im Gerät und wurde nicht gesendet.</numerusform>
            <numerusform>%n weitere Elemente dieses Bereichs waren bereits wie im Gerät und wurden nicht gesendet.</numerusform>
        </translation>
    </message>
    <message>
        <source>Read from device</source>
        <translation>Aus Gerät lesen</translation>
    </message>
    <message>
        <source>Write changes</source>
        <translation>Änderungen schreiben</translation>
    </message>
</context>
<context>
    <name>cambench::CamConWindow</name>
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
        <source>Back up all devices on this &amp;line…</source>
        <translation>Alle Geräte dieser &amp;Leitung sichern…</translation>
    </message>
    <message>
        <source>The device did not identify itself: %1 Your edits are kept.</source>
        <translation>Das Gerät hat sich nicht identifiziert: %1 Ihre Änderungen bleiben erhalten.</translation>
    </message>
    <message>
        <source>Reading the device…</source>
        <translation>Gerät wird gelesen…</translation>
    </message>
    <message>
        <source>Reading the device: %1</source>
        <translation>Gerät lesen: %1</translation>
    </message>
    <message>
        <source>Reading everything the device holds…</source>
        <translation>Der gesamte Inhalt des Geräts wird gelesen…</translation>
    </message>
    <message>
        <source>Everything read from the device.</source>
        <translation>Alles aus dem Gerät gelesen.</translation>
    </message>
    <message>
        <source>Read from the device, except: %1</source>
        <translation>Aus dem Gerät gelesen, außer: %1</translation>
    </message>
    <message>
        <source>Reading the device failed: %1 Your edits are kept.</source>
        <translation>Lesen des Geräts fehlgeschlagen: %1 Ihre Änderungen bleiben erhalten.</translation>
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
        <translation>
            <numerusform>%n Änderung ist nicht ins Gerät geschrieben. Trotzdem schließen?</numerusform>
            <numerusform>%n Änderungen sind nicht ins Gerät geschrieben. Trotzdem schließen?</numerusform>
        </translation>
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
        <source>&amp;New project…</source>
        <translation>&amp;Neues Projekt…</translation>
    </message>
    <message>
        <source>&amp;Open project…</source>
        <translation>Projekt ö&amp;ffnen…</translation>
    </message>
    <message>
        <source>Recent &amp;files</source>
        <translation>&amp;Zuletzt geöffnet</translation>
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
        <source>New project</source>
        <translation>Neues Projekt</translation>
    </message>
    <message numerus="yes">
        <source>%n change(s) are not written or saved. Discard them for a new, empty project?</source>
        <translation>
            <numerusform>%n Änderung ist weder geschrieben noch gespeichert. Für ein neues, leeres Projekt verwerfen?</numerusform>
            <numerusform>%n Änderungen sind weder geschrieben noch gespeichert. Für ein neues, leeres Projekt verwerfen?</numerusform>
        </translation>
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
        <source>The project %1 was not opened.</source>
        <translation>Das Projekt %1 wurde nicht geöffnet.</translation>
    </message>
    <message>
        <source>Project %1 not opened: your edits are unchanged.</source>
        <translation>Projekt %1 nicht geöffnet: Ihre Änderungen sind unverändert.</translation>
    </message>
    <message>
        <source>Project %1 opened. Its content is not on the device until you write it.</source>
        <translation>Projekt %1 geöffnet. Sein Inhalt ist erst im Gerät, wenn Sie ihn schreiben.</translation>
    </message>
    <message>
        <source>No recent projects</source>
        <translation>Keine zuletzt geöffneten Projekte</translation>
    </message>
    <message>
        <source>&amp;Clear list</source>
        <translation>Liste &amp;leeren</translation>
    </message>
    <message>
        <source>Save project</source>
        <translation>Projekt speichern</translation>
    </message>
    <message>
        <source>The device is still being read; the project was not saved. Save again when the reading is done.</source>
        <translation>Das Gerät wird noch gelesen; das Projekt wurde nicht gespeichert. Speichern Sie erneut, wenn das Lesen fertig ist.</translation>
    </message>
    <message>
        <source>The project was not saved.</source>
        <translation>Das Projekt wurde nicht gespeichert.</translation>
    </message>
    <message>
        <source>Project saved to %1.</source>
        <translation>Projekt nach %1 gespeichert.</translation>
    </message>
    <message numerus="yes">
        <source>Project saved to %1. %n value(s) are outside what a write accepts (%2).</source>
        <translation>
            <numerusform>Projekt in %1 gespeichert. %n Wert liegt außerhalb dessen, was ein Schreiben annimmt (%2).</numerusform>
            <numerusform>Projekt in %1 gespeichert. %n Werte liegen außerhalb dessen, was ein Schreiben annimmt (%2).</numerusform>
        </translation>
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
    <message>
        <source>Compare &amp;programs…</source>
        <translation>&amp;Programme vergleichen…</translation>
    </message>
    <message>
        <source>Timing tables at the speed (%1); 0 leaves them out:</source>
        <translation>Schaltzeit-Tabellen bei der Geschwindigkeit (%1); 0 lässt sie weg:</translation>
    </message>
    <message>
        <source>The start pages are read from it; the rest says &quot;not read&quot; until Read everything or Compare.</source>
        <translation>Die Startseiten werden von ihm gelesen; der Rest zeigt „nicht gelesen“ bis Alles lesen oder Mit Gerät vergleichen.</translation>
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
    <message>
        <source>Output %1, cam %2 at %3: never switches on (it vanishes).</source>
        <translation>Ausgang %1, Nocke %2 bei %3: schaltet nie ein (sie verschwindet).</translation>
    </message>
    <message>
        <source>Output %1, cam %2 at %3: switches on at %4, off at %5</source>
        <translation>Ausgang %1, Nocke %2 bei %3: schaltet ein bei %4, aus bei %5</translation>
    </message>
    <message>
        <source>On for %1.</source>
        <translation>Eingeschaltet für %1.</translation>
    </message>
    <message>
        <source>Programmed: on %1, off %2; dead time %3 on, %4 off.</source>
        <translation>Programmiert: ein %1, aus %2; Totzeit %3 ein, %4 aus.</translation>
    </message>
    <message>
        <source>At %1 output %2 switches as drawn. First limit: %3</source>
        <translation>Bei %1 schaltet Ausgang %2 wie gezeichnet. Erste Grenze: %3</translation>
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
    <message>
        <source>Take program %1 from the device</source>
        <translation>Programm %1 aus dem Gerät übernehmen</translation>
    </message>
    <message>
        <source>Take program %1 from the file</source>
        <translation>Programm %1 aus der Datei übernehmen</translation>
    </message>
    <message>
        <source>Take names and dead times</source>
        <translation>Namen und Totzeiten übernehmen</translation>
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
        <translation>
            <numerusform>Die Nocken wurden importiert, aber %n muss korrigiert werden, bevor sie geschrieben werden können (rot markiert):
%1</numerusform>
            <numerusform>Die Nocken wurden importiert, aber %n müssen korrigiert werden, bevor sie geschrieben werden können (rot markiert):
%1</numerusform>
        </translation>
    </message>
    <message>
        <source>Export Cams</source>
        <translation>Nocken exportieren</translation>
    </message>
    <message>
        <source>program-%1.csv</source>
        <translation>programm-%1.csv</translation>
    </message>
    <message>
        <source>Diagram</source>
        <translation>Diagramm</translation>
    </message>
    <message>
        <source>%1 (not read)</source>
        <translation>%1 (nicht gelesen)</translation>
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
        <translation>
            <numerusform>%n Nocken: %1</numerusform>
            <numerusform>%n Nocken: %1</numerusform>
        </translation>
    </message>
    <message>
        <source>, </source>
        <translation>, </translation>
    </message>
</context>
<context>
    <name>cambench::CamPage</name>
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
        <source>Cam programs</source>
        <translation>Nockenprogramme</translation>
    </message>
    <message>
        <source>Program %1 was not read. Your edits are kept.</source>
        <translation>Programm %1 wurde nicht gelesen. Ihre Änderungen bleiben erhalten.</translation>
    </message>
    <message>
        <source>Program %1: nothing to write, the device holds what you see.</source>
        <translation>Programm %1: nichts zu schreiben, das Gerät enthält, was Sie sehen.</translation>
    </message>
    <message>
        <source>Writing program %1…</source>
        <translation>Programm %1 wird geschrieben…</translation>
    </message>
    <message numerus="yes">
        <source>%n other output(s) were already as on the device and not sent.</source>
        <translation>
            <numerusform>%n weiterer Ausgang war bereits wie im Gerät und wurde nicht gesendet.</numerusform>
            <numerusform>%n weitere Ausgänge waren bereits wie im Gerät und wurden nicht gesendet.</numerusform>
        </translation>
    </message>
    <message>
        <source>Output names and dead times not read: %1 Your edits are kept.</source>
        <translation>Ausgangsnamen und Totzeiten nicht gelesen: %1 Ihre Änderungen bleiben erhalten.</translation>
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
    <name>cambench::CamText</name>
    <message>
        <source>no cams</source>
        <translation>keine Nocken</translation>
    </message>
</context>
<context>
    <name>cambench::CapabilityGate</name>
    <message>
        <source>&lt;b&gt;Not available with the connected protocol&lt;/b&gt;</source>
        <translation>&lt;b&gt;Mit dem verbundenen Protokoll nicht verfügbar&lt;/b&gt;</translation>
    </message>
    <message>
        <source>Check what the protocol offers</source>
        <translation>Prüfen, was das Protokoll bietet</translation>
    </message>
</context>
<context>
    <name>cambench::CheckReportDialog</name>
    <message>
        <source>%1 held, %2 refuted, %3 could not tell (%4 requests sent, all reading). Save the report and send it back, so that our tables can be corrected.</source>
        <translation>%1 bestätigt, %2 widerlegt, %3 nicht entscheidbar (%4 Anfragen gesendet, alle lesend). Speichern Sie den Bericht und senden Sie ihn uns, damit wir unsere Tabellen korrigieren können.</translation>
    </message>
    <message>
        <source>Check this device</source>
        <translation>Dieses Gerät prüfen</translation>
    </message>
    <message>
        <source>Save…</source>
        <translation>Speichern…</translation>
    </message>
    <message>
        <source>Save the check report</source>
        <translation>Prüfbericht speichern</translation>
    </message>
    <message>
        <source>Check report (*.json)</source>
        <translation>Prüfbericht (*.json)</translation>
    </message>
    <message>
        <source>The check did not run to its end: %1</source>
        <translation>Die Prüfung lief nicht bis zum Ende: %1</translation>
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
        <source>Cannot write the report to %1: %2</source>
        <translation>Das Protokoll kann nicht nach %1 geschrieben werden: %2</translation>
    </message>
    <message>
        <source>%1 (device: %2)</source>
        <translation>%1 (Gerät: %2)</translation>
    </message>
    <message>
        <source>Read from the device at %1.</source>
        <translation>Aus dem Gerät gelesen am %1.</translation>
    </message>
    <message>
        <source>Not read from the device: the values are this PC&apos;s.</source>
        <translation>Nicht aus dem Gerät gelesen: die Werte stammen von diesem PC.</translation>
    </message>
    <message>
        <source>Offline project: the values are this PC&apos;s.</source>
        <translation>Offline-Projekt: die Werte stammen von diesem PC.</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) in this report are edited on this PC and NOT written to the device; they are marked %1 and show the device&apos;s value beside them.</source>
        <translation>
            <numerusform>%n Wert in diesem Protokoll ist auf diesem PC bearbeitet und NICHT ins Gerät geschrieben; er ist mit %1 markiert und zeigt den Wert des Geräts daneben.</numerusform>
            <numerusform>%n Werte in diesem Protokoll sind auf diesem PC bearbeitet und NICHT ins Gerät geschrieben; sie sind mit %1 markiert und zeigen den Wert des Geräts daneben.</numerusform>
        </translation>
    </message>
    <message>
        <source>Every value in this report is what the device held when it was read.</source>
        <translation>Jeder Wert in diesem Protokoll ist, was das Gerät beim Lesen enthielt.</translation>
    </message>
    <message>
        <source>Offline project: nothing in this report was read from a device.</source>
        <translation>Offline-Projekt: nichts in diesem Protokoll wurde aus einem Gerät gelesen.</translation>
    </message>
    <message>
        <source>Identity read at</source>
        <translation>Kennung gelesen am</translation>
    </message>
    <message>
        <source>offline project</source>
        <translation>Offline-Projekt</translation>
    </message>
    <message>
        <source>Project file</source>
        <translation>Projektdatei</translation>
    </message>
    <message>
        <source>0 … %1</source>
        <translation>0 … %1</translation>
    </message>
    <message>
        <source>Not read from the device: its content is unknown.</source>
        <translation>Nicht aus dem Gerät gelesen: sein Inhalt ist unbekannt.</translation>
    </message>
    <message>
        <source>Not read from the device: these cams exist on this PC only.</source>
        <translation>Nicht aus dem Gerät gelesen: diese Nocken gibt es nur auf diesem PC.</translation>
    </message>
    <message>
        <source>No cams.</source>
        <translation>Keine Nocken.</translation>
    </message>
    <message>
        <source>Cams (on–off)</source>
        <translation>Nocken (ein–aus)</translation>
    </message>
    <message>
        <source>Users</source>
        <translation>Benutzer</translation>
    </message>
    <message>
        <source>No users.</source>
        <translation>Keine Benutzer.</translation>
    </message>
    <message>
        <source>User numbers are access codes: they are not printed.</source>
        <translation>Benutzernummern sind Zugangscodes: sie werden nicht gedruckt.</translation>
    </message>
    <message>
        <source>Number</source>
        <translation>Nummer</translation>
    </message>
    <message>
        <source>Rights</source>
        <translation>Rechte</translation>
    </message>
    <message>
        <source>deleted on this PC, still on the device</source>
        <translation>auf diesem PC gelöscht, noch im Gerät</translation>
    </message>
    <message>
        <source>PLC networks</source>
        <translation>SPS-Netzwerke</translation>
    </message>
    <message>
        <source>No PLC networks read or edited.</source>
        <translation>Keine SPS-Netzwerke gelesen oder bearbeitet.</translation>
    </message>
    <message>
        <source>Network</source>
        <translation>Netzwerk</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Rücksetzen</translation>
    </message>
    <message>
        <source>Symbols by path</source>
        <translation>Symbole je Strompfad</translation>
    </message>
    <message>
        <source>Page %1 of %2</source>
        <translation>Seite %1 von %2</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Modus</translation>
    </message>
    <message>
        <source>Switch-on</source>
        <translation>Einschalten</translation>
    </message>
    <message>
        <source>Switch-off / time</source>
        <translation>Ausschalten / Zeit</translation>
    </message>
    <message>
        <source>Normal</source>
        <translation>Normal</translation>
    </message>
    <message>
        <source>On/off</source>
        <translation>Ein/Aus</translation>
    </message>
    <message>
        <source>Path-time</source>
        <translation>Weg-Zeit</translation>
    </message>
    <message>
        <source>Dead-time modes</source>
        <translation>Totzeit-Modi</translation>
    </message>
    <message>
        <source>Programming program</source>
        <translation>Programmierprogramm</translation>
    </message>
    <message>
        <source>EEPROM lock</source>
        <translation>EEPROM-Sperre</translation>
    </message>
    <message>
        <source>Programming program and EEPROM lock</source>
        <translation>Programmierprogramm und EEPROM-Sperre</translation>
    </message>
    <message>
        <source>Analogue output</source>
        <translation>Analogausgang</translation>
    </message>
    <message>
        <source>Base points</source>
        <translation>Stützpunkte</translation>
    </message>
    <message>
        <source>Analogue cams</source>
        <translation>Analognocken</translation>
    </message>
    <message>
        <source>Dead time on / off</source>
        <translation>Totzeit ein / aus</translation>
    </message>
    <message>
        <source>Shift on / off</source>
        <translation>Verschiebung ein / aus</translation>
    </message>
    <message>
        <source>Shortest cam</source>
        <translation>Kürzeste Nocke</translation>
    </message>
    <message>
        <source>Minimum pulse</source>
        <translation>Mindestimpuls</translation>
    </message>
    <message>
        <source>Limit</source>
        <translation>Grenze</translation>
    </message>
    <message>
        <source>%1 / %2 positions</source>
        <translation>%1 / %2 Positionen</translation>
    </message>
    <message>
        <source>standing still</source>
        <translation>Stillstand</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>Timing at %1</source>
        <translation>Schaltzeiten bei %1</translation>
    </message>
    <message>
        <source>Each edge switches early by speed × its dead time, so that the actuator acts at the programmed position. Dead times as in this report (edits included).</source>
        <translation>Jede Flanke schaltet um Geschwindigkeit × ihre Totzeit früher, damit der Aktor an der programmierten Position wirkt. Totzeiten wie in diesem Bericht (mit Änderungen).</translation>
    </message>
    <message>
        <source>Warnings at this speed: %1</source>
        <translation>Warnungen bei dieser Geschwindigkeit: %1</translation>
    </message>
    <message>
        <source>not read from this device</source>
        <translation>nicht von diesem Gerät gelesen</translation>
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
    <message>
        <source>Cancel reading</source>
        <translation>Lesen abbrechen</translation>
    </message>
    <message>
        <source>Read the device again</source>
        <translation>Gerät erneut lesen</translation>
    </message>
    <message>
        <source>Not connected: compared with the device values read at %1. The device may have changed since.</source>
        <translation>Nicht verbunden: verglichen mit den um %1 gelesenen Werten des Geräts. Das Gerät kann sich seitdem geändert haben.</translation>
    </message>
    <message>
        <source>Not connected, and nothing was read from a device: every edited item is listed as &quot;not read&quot;.</source>
        <translation>Nicht verbunden, und aus keinem Gerät wurde gelesen: jedes bearbeitete Element steht als „nicht gelesen“ da.</translation>
    </message>
    <message>
        <source>Reading what the device holds now…</source>
        <translation>Der jetzige Inhalt des Geräts wird gelesen…</translation>
    </message>
    <message>
        <source>Reading cancelled.</source>
        <translation>Lesen abgebrochen.</translation>
    </message>
    <message>
        <source>The device could not be read: %1</source>
        <translation>Das Gerät konnte nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>Shown: the device values read at %1.</source>
        <translation>Angezeigt: die um %1 gelesenen Werte des Geräts.</translation>
    </message>
    <message>
        <source>Nothing was read from the device: edited items are listed as &quot;not read&quot;.</source>
        <translation>Aus dem Gerät wurde nichts gelesen: bearbeitete Elemente stehen als „nicht gelesen“ da.</translation>
    </message>
    <message>
        <source>Device values read at %1.</source>
        <translation>Werte des Geräts gelesen um %1.</translation>
    </message>
    <message>
        <source>Not read: %1</source>
        <translation>Nicht gelesen: %1</translation>
    </message>
    <message>
        <source>Changed on the device since it was last read (%1)</source>
        <translation>Im Gerät geändert seit dem letzten Lesen (%1)</translation>
    </message>
    <message>
        <source>The edits hold a copy of the values of %1, made when this device came on the line.</source>
        <translation>Die Bearbeitungen enthalten eine Kopie der Werte von %1, angelegt, als dieses Gerät an die Leitung kam.</translation>
    </message>
    <message>
        <source>Copy to write</source>
        <translation>Zu schreibende Kopie</translation>
    </message>
</context>
<context>
    <name>cambench::CompareProgramsDialog</name>
    <message>
        <source>Compare</source>
        <translation>Vergleichen</translation>
    </message>
    <message>
        <source>Hide outputs without a difference</source>
        <translation>Ausgänge ohne Unterschied ausblenden</translation>
    </message>
    <message>
        <source>Compare programs</source>
        <translation>Programme vergleichen</translation>
    </message>
    <message>
        <source>A (before)</source>
        <translation>A (vorher)</translation>
    </message>
    <message>
        <source>B (after)</source>
        <translation>B (nachher)</translation>
    </message>
    <message>
        <source>the same in both</source>
        <translation>in beiden gleich</translation>
    </message>
    <message>
        <source>changed: A dashed, B solid, moved edges marked</source>
        <translation>geändert: A gestrichelt, B gefüllt, verschobene Kanten markiert</translation>
    </message>
    <message>
        <source>only in A</source>
        <translation>nur in A</translation>
    </message>
    <message>
        <source>only in B</source>
        <translation>nur in B</translation>
    </message>
    <message>
        <source>Edited on this PC</source>
        <translation>Auf diesem PC bearbeitet</translation>
    </message>
    <message>
        <source>On the device</source>
        <translation>Im Gerät</translation>
    </message>
    <message>
        <source>Project file</source>
        <translation>Projektdatei</translation>
    </message>
    <message>
        <source>CSV cam file</source>
        <translation>CSV-Nockendatei</translation>
    </message>
    <message>
        <source>Choose…</source>
        <translation>Auswählen…</translation>
    </message>
    <message>
        <source>Source:</source>
        <translation>Quelle:</translation>
    </message>
    <message>
        <source>Program:</source>
        <translation>Programm:</translation>
    </message>
    <message>
        <source>File:</source>
        <translation>Datei:</translation>
    </message>
    <message>
        <source>CSV cam files (*.csv)</source>
        <translation>CSV-Nockendateien (*.csv)</translation>
    </message>
    <message>
        <source>CamBench projects (*.json)</source>
        <translation>CamBench-Projekte (*.json)</translation>
    </message>
    <message>
        <source>(none chosen)</source>
        <translation>(keine ausgewählt)</translation>
    </message>
    <message>
        <source>Program %1 is not on this PC yet: read it from the device or open a project.</source>
        <translation>Programm %1 ist noch nicht auf diesem PC: Lesen Sie es aus dem Gerät oder öffnen Sie ein Projekt.</translation>
    </message>
    <message>
        <source>edited on this PC, program %1</source>
        <translation>auf diesem PC bearbeitet, Programm %1</translation>
    </message>
    <message>
        <source>Read program %1</source>
        <translation>Programm %1 lesen</translation>
    </message>
    <message>
        <source>the device, program %1, read at %2</source>
        <translation>das Gerät, Programm %1, gelesen um %2</translation>
    </message>
    <message>
        <source>Choose the project file.</source>
        <translation>Wählen Sie die Projektdatei.</translation>
    </message>
    <message>
        <source>%1, program %2</source>
        <translation>%1, Programm %2</translation>
    </message>
    <message>
        <source>%1 holds no program %2.</source>
        <translation>%1 enthält kein Programm %2.</translation>
    </message>
    <message>
        <source>Choose the CSV file.</source>
        <translation>Wählen Sie die CSV-Datei.</translation>
    </message>
    <message>
        <source>Reading…</source>
        <translation>Lesen…</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message numerus="yes">
        <source>A: %1. B: %2. %n difference(s).</source>
        <translation>
            <numerusform>A: %1. B: %2. %n Unterschied.</numerusform>
            <numerusform>A: %1. B: %2. %n Unterschiede.</numerusform>
        </translation>
    </message>
    <message>
        <source>output %1, cam %2: %3 → %4</source>
        <translation>Ausgang %1, Nocken %2: %3 → %4</translation>
    </message>
    <message>
        <source>output %1, cam %2 (in B %3): %4 → %5</source>
        <translation>Ausgang %1, Nocken %2 (in B %3): %4 → %5</translation>
    </message>
    <message>
        <source>output %1: cam %2 only in A</source>
        <translation>Ausgang %1: Nocken %2 nur in A</translation>
    </message>
    <message>
        <source>output %1: cam %2 only in B</source>
        <translation>Ausgang %1: Nocken %2 nur in B</translation>
    </message>
    <message>
        <source>Write checked to the device…</source>
        <translation>Angehakte ins Gerät schreiben…</translation>
    </message>
    <message>
        <source>Writes the checked differences to the device side&apos;s program: its outputs as the device held them, with those differences made like the other side.</source>
        <translation>Schreibt die angehakten Unterschiede in das Programm der Geräteseite: seine Ausgänge, wie das Gerät sie hatte, mit diesen Unterschieden wie auf der anderen Seite.</translation>
    </message>
    <message>
        <source>%1 Reading both sides again…</source>
        <translation>%1 Beide Seiten werden neu gelesen…</translation>
    </message>
    <message>
        <source>Nothing written: %1</source>
        <translation>Nichts geschrieben: %1</translation>
    </message>
    <message numerus="yes">
        <source>output %1 (%n difference(s))</source>
        <translation>
            <numerusform>Ausgang %1 (%n Unterschied)</numerusform>
            <numerusform>Ausgang %1 (%n Unterschiede)</numerusform>
        </translation>
    </message>
    <message>
        <source>Write to the device, program %1: %2?</source>
        <translation>Ins Gerät schreiben, Programm %1: %2?</translation>
    </message>
    <message>
        <source>Each output is written whole: as read from the device (%1), with the checked differences made like the other side. Cam outputs switch as soon as the device takes them.</source>
        <translation>Jeder Ausgang wird ganz geschrieben: wie vom Gerät gelesen (%1), mit den angehakten Unterschieden wie auf der anderen Seite. Nockenausgänge schalten, sobald das Gerät sie übernimmt.</translation>
    </message>
    <message>
        <source>Output(s) %1 of program %2 hold edits on this PC that are not on the device: they are replaced by what is written (Edit → Undo brings them back).</source>
        <translation>Ausgang/Ausgänge %1 von Programm %2 haben Änderungen auf diesem PC, die nicht im Gerät sind: Sie werden durch das Geschriebene ersetzt (Bearbeiten → Rückgängig holt sie zurück).</translation>
    </message>
    <message>
        <source>Write checked differences</source>
        <translation>Angehakte Unterschiede schreiben</translation>
    </message>
    <message>
        <source>Write to device</source>
        <translation>Ins Gerät schreiben</translation>
    </message>
    <message>
        <source>Apply differences from Compare programs</source>
        <translation>Unterschiede aus „Programme vergleichen“ übernehmen</translation>
    </message>
    <message>
        <source>Writing program %1…</source>
        <translation>Programm %1 wird geschrieben…</translation>
    </message>
    <message>
        <source>Program %1: %2</source>
        <translation>Programm %1: %2</translation>
    </message>
</context>
<context>
    <name>cambench::Compax3Gui</name>
    <message>
        <source>Use dictionary</source>
        <translation>Objektverzeichnis verwenden</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) typed in on this PC are NOT on the drive; the values below are the drive&apos;s.</source>
        <translation>
            <numerusform>%n auf diesem PC eingegebener Wert ist NICHT im Antrieb; die Werte unten sind die des Antriebs.</numerusform>
            <numerusform>%n auf diesem PC eingegebene Werte sind NICHT im Antrieb; die Werte unten sind die des Antriebs.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>cambench::Compax3MotionPage</name>
    <message>
        <source>Motion</source>
        <translation>Bewegung</translation>
    </message>
    <message>
        <source>0 (homing)</source>
        <translation>0 (Referenzfahrt)</translation>
    </message>
    <message>
        <source>Enable…</source>
        <translation>Freigeben…</translation>
    </message>
    <message>
        <source>Disable</source>
        <translation>Sperren</translation>
    </message>
    <message>
        <source>Jog +…</source>
        <translation>Tippen +…</translation>
    </message>
    <message>
        <source>Jog −…</source>
        <translation>Tippen −…</translation>
    </message>
    <message>
        <source>Start set…</source>
        <translation>Satz starten…</translation>
    </message>
    <message>
        <source>Power</source>
        <translation>Leistung</translation>
    </message>
    <message>
        <source>Jog (moves until STOP)</source>
        <translation>Tippen (fährt bis STOPP)</translation>
    </message>
    <message>
        <source>Positioning set</source>
        <translation>Positioniersatz</translation>
    </message>
    <message>
        <source>Set:</source>
        <translation>Satz:</translation>
    </message>
    <message>
        <source>Target:</source>
        <translation>Ziel:</translation>
    </message>
    <message>
        <source>Velocity:</source>
        <translation>Geschwindigkeit:</translation>
    </message>
    <message>
        <source>Acceleration:</source>
        <translation>Beschleunigung:</translation>
    </message>
    <message>
        <source>Every motion asks first. A command that moves the axis is sent once: when its answer is lost, CamBench reads the drive&apos;s state and says it instead of sending it again.</source>
        <translation>Jede Bewegung fragt zuerst. Ein Befehl, der die Achse bewegt, wird einmal gesendet: Geht seine Antwort verloren, liest CamBench den Zustand des Antriebs und nennt ihn, statt den Befehl noch einmal zu senden.</translation>
    </message>
    <message>
        <source>No drive connected.</source>
        <translation>Kein Antrieb verbunden.</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Sent: %1. Now %2.</source>
        <translation>Gesendet: %1. Jetzt %2.</translation>
    </message>
    <message>
        <source>The axis moves until STOP (or Escape) is pressed. Make sure nobody is at the axis.</source>
        <translation>Die Achse fährt, bis STOPP (oder Escape) gedrückt wird. Stellen Sie sicher, dass niemand an der Achse ist.</translation>
    </message>
    <message>
        <source>The axis is powered and holds its position. Make sure nobody is at the axis.</source>
        <translation>Die Achse wird bestromt und hält ihre Position. Stellen Sie sicher, dass niemand an der Achse ist.</translation>
    </message>
    <message>
        <source>%1 on drive %2?</source>
        <translation>%1 am Antrieb %2?</translation>
    </message>
    <message>
        <source>The axis moves to the set&apos;s target at its velocity. STOP (or Escape) stops it. Make sure nobody is at the axis.</source>
        <translation>Die Achse fährt mit der Geschwindigkeit des Satzes zu seinem Ziel. STOPP (oder Escape) hält sie an. Stellen Sie sicher, dass niemand an der Achse ist.</translation>
    </message>
    <message>
        <source>Enable</source>
        <translation>Freigeben</translation>
    </message>
    <message>
        <source>Jog</source>
        <translation>Tippen</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Starten</translation>
    </message>
    <message>
        <source>Stops the drive and drops what waits for the line: the STOP above every page. Escape does the same.</source>
        <translation>Stoppt den Antrieb und verwirft, was auf die Leitung wartet: der STOPP über jeder Seite. Escape tut dasselbe.</translation>
    </message>
    <message>
        <source>Mode (1905.n):</source>
        <translation>Modus (1905.n):</translation>
    </message>
    <message>
        <source>Motion is off while the STOP cannot reach the drive.</source>
        <translation>Bewegung ist gesperrt, solange der STOPP den Antrieb nicht erreicht.</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>nicht gelesen</translation>
    </message>
    <message>
        <source>Read set %1</source>
        <translation>Satz %1 lesen</translation>
    </message>
    <message>
        <source>Set %1 not read: %2</source>
        <translation>Satz %1 nicht gelesen: %2</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Set %1 is not read from the drive yet: reading it; start it then.</source>
        <translation>Satz %1 ist noch nicht vom Antrieb gelesen: er wird gelesen; danach starten.</translation>
    </message>
    <message>
        <source>%1: %2 → %3 (written first)</source>
        <translation>%1: %2 → %3 (wird zuerst geschrieben)</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>Velocity</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>Deceleration:</source>
        <translation>Verzögerung:</translation>
    </message>
    <message>
        <source>%1 (read at %2)</source>
        <translation>%1 (gelesen am %2)</translation>
    </message>
    <message>
        <source>Switch drive %1 powerless?</source>
        <translation>Antrieb %1 stromlos schalten?</translation>
    </message>
    <message>
        <source>Power is dropped: the motor no longer holds the axis. A hanging (vertical) axis falls unless its brake holds it; a moving axis runs out as the drive is set. Make sure nobody is at the axis.</source>
        <translation>Die Bestromung wird abgeschaltet: der Motor hält die Achse nicht mehr. Eine hängende (senkrechte) Achse fällt, wenn ihre Bremse sie nicht hält; eine fahrende Achse läuft aus, wie der Antrieb eingestellt ist. Stellen Sie sicher, dass niemand an der Achse ist.</translation>
    </message>
    <message>
        <source>Set %1 as read from the drive at %2; read again before anything is sent: if the drive then holds other values, nothing is sent and you are asked again.</source>
        <translation>Satz %1 wie am %2 aus dem Antrieb gelesen; vor dem Senden wird er erneut gelesen: enthält der Antrieb dann andere Werte, wird nichts gesendet und Sie werden erneut gefragt.</translation>
    </message>
    <message>
        <source>%1: %2 (as read)</source>
        <translation>%1: %2 (wie gelesen)</translation>
    </message>
    <message>
        <source>Acceleration</source>
        <translation>Beschleunigung</translation>
    </message>
    <message>
        <source>Deceleration</source>
        <translation>Verzögerung</translation>
    </message>
    <message>
        <source>Mode (1905.%1): %2 (as read)</source>
        <translation>Modus (1905.%1): %2 (wie gelesen)</translation>
    </message>
</context>
<context>
    <name>cambench::Compax3ObjectModel</name>
    <message>
        <source>(not in the dictionary)</source>
        <translation>(nicht im Objektverzeichnis)</translation>
    </message>
    <message>
        <source>read-only</source>
        <translation>nur lesbar</translation>
    </message>
    <message>
        <source>function (written only)</source>
        <translation>Funktion (nur schreiben)</translation>
    </message>
    <message>
        <source>control word: Motion page</source>
        <translation>Steuerwort: Seite Bewegung</translation>
    </message>
    <message>
        <source>Object</source>
        <translation>Objekt</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>On the drive</source>
        <translation>Im Antrieb</translation>
    </message>
    <message>
        <source>New value</source>
        <translation>Neuer Wert</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <source>Range</source>
        <translation>Bereich</translation>
    </message>
    <message>
        <source>Other objects</source>
        <translation>Weitere Objekte</translation>
    </message>
    <message>
        <source>refused</source>
        <translation>abgelehnt</translation>
    </message>
    <message>
        <source>Stale: read %1, the connection was lost since.</source>
        <translation>Veraltet: gelesen %1, seitdem ging die Verbindung verloren.</translation>
    </message>
    <message>
        <source>Read %1.</source>
        <translation>Gelesen %1.</translation>
    </message>
    <message>
        <source>Not read yet.</source>
        <translation>Noch nicht gelesen.</translation>
    </message>
    <message>
        <source>Edited on this PC, not on the drive yet: Write changes sends it.</source>
        <translation>Auf diesem PC geändert, noch nicht im Antrieb: „Änderungen schreiben“ sendet es.</translation>
    </message>
    <message>
        <source>Type a new value (decimal point: 12.5)</source>
        <translation>Neuen Wert eingeben (Dezimalpunkt: 12.5)</translation>
    </message>
    <message>
        <source>unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <source>not on this drive</source>
        <translation>nicht auf diesem Antrieb</translation>
    </message>
    <message>
        <source>The drive does not have this object: %1</source>
        <translation>Der Antrieb hat dieses Objekt nicht: %1</translation>
    </message>
    <message>
        <source>Typed in, but the dictionary in use refuses it: %1</source>
        <translation>Eingetippt, aber das benutzte Wörterbuch lehnt es ab: %1</translation>
    </message>
</context>
<context>
    <name>cambench::Compax3ObjectsPage</name>
    <message>
        <source>Objects</source>
        <translation>Objekte</translation>
    </message>
    <message>
        <source>Write changes…</source>
        <translation>Änderungen schreiben…</translation>
    </message>
    <message>
        <source>Search objects (number, name, group)…</source>
        <translation>Objekte suchen (Nummer, Name, Gruppe)…</translation>
    </message>
    <message>
        <source>Read all</source>
        <translation>Alle lesen</translation>
    </message>
    <message>
        <source>Discard changes</source>
        <translation>Änderungen verwerfen</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Verwerfen</translation>
    </message>
    <message numerus="yes">
        <source>Discard %n value(s) typed in but not written?</source>
        <translation>
            <numerusform>%n eingegebenen, nicht geschriebenen Wert verwerfen?</numerusform>
            <numerusform>%n eingegebene, nicht geschriebene Werte verwerfen?</numerusform>
        </translation>
    </message>
    <message>
        <source>Load dictionary…</source>
        <translation>Objektverzeichnis laden…</translation>
    </message>
    <message>
        <source>Load object dictionary</source>
        <translation>Objektverzeichnis laden</translation>
    </message>
    <message>
        <source>Compax3 dictionaries (*.json)</source>
        <translation>Compax3-Objektverzeichnisse (*.json)</translation>
    </message>
    <message>
        <source>Object, e.g. O 1234,5</source>
        <translation>Objekt, z. B. O 1234,5</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Read</source>
        <translation>Lesen</translation>
    </message>
    <message>
        <source>Write…</source>
        <translation>Schreiben…</translation>
    </message>
    <message>
        <source>Any object by number:</source>
        <translation>Beliebiges Objekt nach Nummer:</translation>
    </message>
    <message>
        <source>Read objects</source>
        <translation>Objekte lesen</translation>
    </message>
    <message>
        <source>Not read: %1</source>
        <translation>Nicht gelesen: %1</translation>
    </message>
    <message numerus="yes">
        <source>Read %n object(s) at %1.</source>
        <translation>
            <numerusform>%n Objekt um %1 gelesen.</numerusform>
            <numerusform>%n Objekte um %1 gelesen.</numerusform>
        </translation>
    </message>
    <message>
        <source>Read %1 objects; the drive refused %2 (hover over &quot;refused&quot; for its answer).</source>
        <translation>%1 Objekte gelesen; der Antrieb lehnte %2 ab (seine Antwort steht im Tooltip von „abgelehnt“).</translation>
    </message>
    <message>
        <source>Nothing to write: no value is typed in.</source>
        <translation>Nichts zu schreiben: kein Wert ist eingegeben.</translation>
    </message>
    <message>
        <source>Not connected to a drive: the values stay typed in.</source>
        <translation>Nicht mit einem Antrieb verbunden: die Werte bleiben eingegeben.</translation>
    </message>
    <message>
        <source>%1: %2 → %3</source>
        <translation>%1: %2 → %3</translation>
    </message>
    <message>
        <source>(not read)</source>
        <translation>(nicht gelesen)</translation>
    </message>
    <message>
        <source>Write</source>
        <translation>Schreiben</translation>
    </message>
    <message numerus="yes">
        <source>Write %n value(s) to the drive %1?</source>
        <translation>
            <numerusform>%n Wert in den Antrieb %1 schreiben?</numerusform>
            <numerusform>%n Werte in den Antrieb %1 schreiben?</numerusform>
        </translation>
    </message>
    <message>
        <source>Write objects</source>
        <translation>Objekte schreiben</translation>
    </message>
    <message>
        <source>Not written: %1</source>
        <translation>Nicht geschrieben: %1</translation>
    </message>
    <message>
        <source>1100.3 is the control word, which moves the axis: use the Motion page.</source>
        <translation>1100.3 ist das Steuerwort, das die Achse bewegt: benutzen Sie die Seite Bewegung.</translation>
    </message>
    <message>
        <source>Load dictionary</source>
        <translation>Objektverzeichnis laden</translation>
    </message>
    <message>
        <source>The dictionary was not loaded: %1</source>
        <translation>Das Objektverzeichnis wurde nicht geladen: %1</translation>
    </message>
    <message>
        <source>Load</source>
        <translation>Laden</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) are typed in but not written. Load the dictionary anyway? Values of objects it still lists stay typed in.</source>
        <translation>
            <numerusform>%n Wert ist eingegeben, aber nicht geschrieben. Das Objektverzeichnis trotzdem laden? Werte von Objekten, die es weiter enthält, bleiben eingegeben.</numerusform>
            <numerusform>%n Werte sind eingegeben, aber nicht geschrieben. Das Objektverzeichnis trotzdem laden? Werte von Objekten, die es weiter enthält, bleiben eingegeben.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Loaded %n object(s) from %1.</source>
        <translation>
            <numerusform>%n Objekt aus %1 geladen.</numerusform>
            <numerusform>%n Objekte aus %1 geladen.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) typed in, not on the drive yet: Write changes sends them.</source>
        <translation>
            <numerusform>%n Wert eingegeben, noch nicht im Antrieb: „Änderungen schreiben“ sendet ihn.</numerusform>
            <numerusform>%n Werte eingegeben, noch nicht im Antrieb: „Änderungen schreiben“ sendet sie.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The loaded dictionary refuses %n typed value(s); they stay typed in and are not written until corrected: %1</source>
        <translation>
            <numerusform>Das geladene Wörterbuch lehnt %n eingetippten Wert ab; er bleibt eingetippt und wird erst nach der Korrektur geschrieben: %1</numerusform>
            <numerusform>Das geladene Wörterbuch lehnt %n eingetippte Werte ab; sie bleiben eingetippt und werden erst nach der Korrektur geschrieben: %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n object(s) are not on this drive (greyed).</source>
        <translation>
            <numerusform>%n Objekt ist nicht auf diesem Antrieb (grau).</numerusform>
            <numerusform>%n Objekte sind nicht auf diesem Antrieb (grau).</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Nothing was written: the dictionary in use refuses %n typed value(s) (they stay typed in; correct or clear them): %1</source>
        <translation>
            <numerusform>Nichts wurde geschrieben: das benutzte Wörterbuch lehnt %n eingetippten Wert ab (er bleibt eingetippt; korrigieren oder leeren): %1</numerusform>
            <numerusform>Nichts wurde geschrieben: das benutzte Wörterbuch lehnt %n eingetippte Werte ab (sie bleiben eingetippt; korrigieren oder leeren): %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>cambench::Compax3Page</name>
    <message>
        <source>Read drive status</source>
        <translation>Antriebsstatus lesen</translation>
    </message>
</context>
<context>
    <name>cambench::Compax3ParametersPage</name>
    <message>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>No file compared yet.</source>
        <translation>Noch keine Datei verglichen.</translation>
    </message>
    <message>
        <source>Write to another drive type</source>
        <translation>In einen anderen Antriebstyp schreiben</translation>
    </message>
    <message>
        <source>Save drive to file…</source>
        <translation>Antrieb in Datei sichern…</translation>
    </message>
    <message>
        <source>Save drive parameters</source>
        <translation>Antriebsparameter sichern</translation>
    </message>
    <message>
        <source>Compax3 parameter files (*.json)</source>
        <translation>Compax3-Parameterdateien (*.json)</translation>
    </message>
    <message>
        <source>Compare with file…</source>
        <translation>Mit Datei vergleichen…</translation>
    </message>
    <message>
        <source>Compare with file</source>
        <translation>Mit Datei vergleichen</translation>
    </message>
    <message>
        <source>Write selected differences…</source>
        <translation>Ausgewählte Unterschiede schreiben…</translation>
    </message>
    <message>
        <source>Write whole file…</source>
        <translation>Ganze Datei schreiben…</translation>
    </message>
    <message>
        <source>Only when you know the objects mean the same on both drive types.</source>
        <translation>Nur wenn Sie wissen, dass die Objekte in beiden Antriebstypen dasselbe bedeuten.</translation>
    </message>
    <message>
        <source>Object</source>
        <translation>Objekt</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>In the file</source>
        <translation>In der Datei</translation>
    </message>
    <message>
        <source>On the drive</source>
        <translation>Im Antrieb</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Sichern</translation>
    </message>
    <message>
        <source>No file was saved: %1</source>
        <translation>Es wurde keine Datei gesichert: %1</translation>
    </message>
    <message>
        <source>Saved %1 objects to %2, but the file is incomplete: the drive refused %3 objects.</source>
        <translation>%1 Objekte in %2 gesichert, aber die Datei ist unvollständig: der Antrieb lehnte %3 Objekte ab.</translation>
    </message>
    <message>
        <source>Incomplete: %1 objects refused.</source>
        <translation>Unvollständig: %1 Objekte abgelehnt.</translation>
    </message>
    <message>
        <source>Saved %1 objects of drive %2 to %3.</source>
        <translation>%1 Objekte des Antriebs %2 in %3 gesichert.</translation>
    </message>
    <message>
        <source>Compare</source>
        <translation>Vergleichen</translation>
    </message>
    <message>
        <source>%1: %2 objects of %3 (serial number %4), saved %5.</source>
        <translation>%1: %2 Objekte von %3 (Seriennummer %4), gesichert %5.</translation>
    </message>
    <message>
        <source>Not compared: %1</source>
        <translation>Nicht verglichen: %1</translation>
    </message>
    <message>
        <source>Equal: the drive holds all %1 values of the file.</source>
        <translation>Gleich: der Antrieb enthält alle %1 Werte der Datei.</translation>
    </message>
    <message>
        <source>%1 of %2 objects differ.</source>
        <translation>%1 von %2 Objekten unterscheiden sich.</translation>
    </message>
    <message>
        <source>The file is from a drive of type %1, this one is of type %2.</source>
        <translation>Die Datei stammt von einem Antrieb des Typs %1, dieser ist vom Typ %2.</translation>
    </message>
    <message>
        <source>Compare with a file first.</source>
        <translation>Vergleichen Sie zuerst mit einer Datei.</translation>
    </message>
    <message>
        <source>No difference is ticked: nothing to write.</source>
        <translation>Kein Unterschied ist angehakt: nichts zu schreiben.</translation>
    </message>
    <message numerus="yes">
        <source>%n selected object(s)</source>
        <translation>
            <numerusform>%n ausgewähltes Objekt</numerusform>
            <numerusform>%n ausgewählte Objekte</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>the whole file (%n object(s))</source>
        <translation>
            <numerusform>die ganze Datei (%n Objekt)</numerusform>
            <numerusform>die ganze Datei (%n Objekte)</numerusform>
        </translation>
    </message>
    <message>
        <source>Write</source>
        <translation>Schreiben</translation>
    </message>
    <message>
        <source>Write %1 of %2 to drive %3?</source>
        <translation>%1 aus %2 in den Antrieb %3 schreiben?</translation>
    </message>
    <message>
        <source>The file is checked against the drive first; then only objects that differ are written, each read back.%1</source>
        <translation>Die Datei wird zuerst mit dem Antrieb abgeglichen; dann werden nur abweichende Objekte geschrieben und jedes zurückgelesen.%1</translation>
    </message>
    <message>
        <source> Afterwards the sets are stored in flash.</source>
        <translation> Danach werden die Sätze im Flash gespeichert.</translation>
    </message>
    <message>
        <source>Write parameters</source>
        <translation>Parameter schreiben</translation>
    </message>
    <message>
        <source>To replace a drive: save the old drive&apos;s parameters to a file (or take one saved before), connect the new drive, compare it with the file, then write the differences and store the sets.</source>
        <translation>Einen Antrieb tauschen: die Parameter des alten Antriebs in eine Datei sichern (oder eine früher gesicherte nehmen), den neuen Antrieb verbinden, ihn mit der Datei vergleichen, dann die Unterschiede schreiben und die Sätze speichern.</translation>
    </message>
    <message>
        <source>Store the written sets in the drive&apos;s flash afterwards (1904.n = $32)</source>
        <translation>Die geschriebenen Sätze danach im Flash des Antriebs speichern (1904.n = $32)</translation>
    </message>
    <message>
        <source>Not on this drive (recorded in the file as absent): %1.</source>
        <translation>Nicht auf diesem Antrieb (in der Datei als fehlend vermerkt): %1.</translation>
    </message>
    <message>
        <source>Never saved, being control words or functions: %1.</source>
        <translation>Nie gespeichert, da Steuerwörter oder Funktionen: %1.</translation>
    </message>
    <message>
        <source>not on the file&apos;s drive</source>
        <translation>nicht auf dem Antrieb der Datei</translation>
    </message>
    <message>
        <source>Not compared, being control words or functions a file never writes: %1.</source>
        <translation>Nicht verglichen, da Steuerwörter oder Funktionen, die eine Datei nie schreibt: %1.</translation>
    </message>
</context>
<context>
    <name>cambench::Compax3Report</name>
    <message>
        <source>Last error (550.1): %1</source>
        <translation>Letzter Fehler (550.1): %1</translation>
    </message>
    <message>
        <source>Status word (1000.3): %1; set: %2</source>
        <translation>Statuswort (1000.3): %1; gesetzt: %2</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>Object</source>
        <translation>Objekt</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <source>Not on this drive: %1.</source>
        <translation>Nicht auf diesem Antrieb: %1.</translation>
    </message>
    <message>
        <source>%1 not read: %2</source>
        <translation>%1 nicht gelesen: %2</translation>
    </message>
    <message>
        <source>Read the drive for the report</source>
        <translation>Antrieb für den Bericht lesen</translation>
    </message>
    <message>
        <source>Not read from the drive for this report.</source>
        <translation>Für diesen Bericht nicht aus dem Antrieb gelesen.</translation>
    </message>
    <message>
        <source>Read from the drive at %1.</source>
        <translation>Aus dem Antrieb gelesen am %1.</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>Antrieb</translation>
    </message>
    <message>
        <source>Serial number %1, type %2</source>
        <translation>Seriennummer %1, Typ %2</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Not read: %1</source>
        <translation>Nicht gelesen: %1</translation>
    </message>
    <message>
        <source>Parameter set</source>
        <translation>Parametersatz</translation>
    </message>
</context>
<context>
    <name>cambench::Compax3StatusPage</name>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Acknowledge error…</source>
        <translation>Fehler quittieren…</translation>
    </message>
    <message>
        <source>Switches the drive off and on again (control word 0, then 1): the rising edge acknowledges the error and powers the axis.</source>
        <translation>Schaltet den Antrieb aus und wieder ein (Steuerwort 0, dann 1): die steigende Flanke quittiert den Fehler und bestromt die Achse.</translation>
    </message>
    <message>
        <source>Status word 1 (object 1000.3), bit 0 first. The meanings of the bits and error numbers come from a public client, not from Parker&apos;s manual.</source>
        <translation>Statuswort 1 (Objekt 1000.3), Bit 0 zuerst. Die Bedeutungen der Bits und Fehlernummern stammen aus einem öffentlichen Client, nicht aus Parkers Handbuch.</translation>
    </message>
    <message>
        <source>Last error:</source>
        <translation>Letzter Fehler:</translation>
    </message>
    <message>
        <source>Axis:</source>
        <translation>Achse:</translation>
    </message>
    <message>
        <source>Acknowledge</source>
        <translation>Quittieren</translation>
    </message>
    <message>
        <source>Acknowledge the error and power the axis of drive %1?</source>
        <translation>Den Fehler quittieren und die Achse des Antriebs %1 bestromen?</translation>
    </message>
    <message>
        <source>Not acknowledged: %1</source>
        <translation>Nicht quittiert: %1</translation>
    </message>
    <message>
        <source>Acknowledged; last error now: %1.</source>
        <translation>Quittiert; letzter Fehler jetzt: %1.</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>A powerless drive is switched off and on again; it holds its position with power afterwards. A powered drive is left as it is (nothing is sent). Make sure nobody is at the axis.</source>
        <translation>Ein stromloser Antrieb wird aus- und wieder eingeschaltet; danach hält er seine Position bestromt. Ein bestromter Antrieb bleibt, wie er ist (nichts wird gesendet). Stellen Sie sicher, dass niemand an der Achse ist.</translation>
    </message>
    <message>
        <source>Acknowledged by the drive; %1</source>
        <translation>Vom Antrieb quittiert; %1</translation>
    </message>
</context>
<context>
    <name>cambench::Compax3WatchPage</name>
    <message>
        <source>Watch</source>
        <translation>Beobachten</translation>
    </message>
    <message>
        <source>Object to watch, e.g. 680.5</source>
        <translation>Zu beobachtendes Objekt, z. B. 680.5</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
    <message>
        <source>Remove selected</source>
        <translation>Auswahl entfernen</translation>
    </message>
    <message>
        <source>Object</source>
        <translation>Objekt</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Read</source>
        <translation>Lesen</translation>
    </message>
    <message>
        <source>%1 is a function: it is written, never read.</source>
        <translation>%1 ist eine Funktion: sie wird geschrieben, nie gelesen.</translation>
    </message>
    <message>
        <source>Read watched objects</source>
        <translation>Beobachtete Objekte lesen</translation>
    </message>
    <message>
        <source>refused</source>
        <translation>abgelehnt</translation>
    </message>
</context>
<context>
    <name>cambench::Compax3Window</name>
    <message>
        <source>Identify drive</source>
        <translation>Antrieb identifizieren</translation>
    </message>
    <message>
        <source>%1, serial number %2</source>
        <translation>%1, Seriennummer %2</translation>
    </message>
    <message>
        <source>No Compax3 identified itself: %1</source>
        <translation>Kein Compax3 hat sich zu erkennen gegeben: %1</translation>
    </message>
    <message>
        <source>Unwritten values</source>
        <translation>Nicht geschriebene Werte</translation>
    </message>
    <message numerus="yes">
        <source>%n value(s) typed in on the Objects page are not on the drive.</source>
        <translation>
            <numerusform>%n auf der Seite Objekte eingegebener Wert ist nicht im Antrieb.</numerusform>
            <numerusform>%n auf der Seite Objekte eingegebene Werte sind nicht im Antrieb.</numerusform>
        </translation>
    </message>
    <message>
        <source>Closing drops them.</source>
        <translation>Beim Schließen gehen sie verloren.</translation>
    </message>
    <message>
        <source>Close and drop them</source>
        <translation>Schließen und verwerfen</translation>
    </message>
</context>
<context>
    <name>cambench::ConnectionIndicator</name>
    <message>
        <source>No answer since %1 (%2)</source>
        <translation>Keine Antwort seit %1 (%2)</translation>
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
        <source>Protocol:</source>
        <translation>Protokoll:</translation>
    </message>
    <message>
        <source>Baud rate:</source>
        <translation>Baudrate:</translation>
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
    <message numerus="yes">
        <source>%n device(s) found</source>
        <translation>
            <numerusform>%n Gerät gefunden</numerusform>
            <numerusform>%n Geräte gefunden</numerusform>
        </translation>
    </message>
    <message>
        <source>Connection</source>
        <translation>Verbindung</translation>
    </message>
    <message>
        <source>Not connected to %1: %2
Check the port name (a serial port, tcp://host:port for a device server), the protocol and baud rate, the cable and the device&apos;s power, then press Connect again.</source>
        <translation>Nicht verbunden mit %1: %2
Prüfen Sie den Schnittstellennamen (eine serielle Schnittstelle, tcp://Host:Port für einen Geräteserver), Protokoll und Baudrate, das Kabel und die Stromversorgung des Geräts und drücken Sie dann erneut „Verbinden“.</translation>
    </message>
    <message>
        <source>(no port given)</source>
        <translation>(keine Schnittstelle angegeben)</translation>
    </message>
    <message>
        <source>Detect</source>
        <translation>Gerät suchen</translation>
    </message>
    <message>
        <source>Find out what is on this port: each device family&apos;s protocols are tried at their usual line settings, with identification queries only.</source>
        <translation>Herausfinden, was an dieser Schnittstelle hängt: Die Protokolle jeder Gerätefamilie werden mit ihren üblichen Leitungseinstellungen versucht, nur mit Abfragen zur Kennung.</translation>
    </message>
    <message>
        <source>Device family:</source>
        <translation>Gerätefamilie:</translation>
    </message>
    <message>
        <source>%1 (not built into this CamBench yet)</source>
        <translation>%1 (in dieses CamBench noch nicht eingebaut)</translation>
    </message>
    <message>
        <source>Its protocol, simulator and pages are not built yet.</source>
        <translation>Ihr Protokoll, Simulator und ihre Seiten sind noch nicht gebaut.</translation>
    </message>
    <message>
        <source>Choose or type a port first.</source>
        <translation>Wählen oder tippen Sie zuerst eine Schnittstelle.</translation>
    </message>
    <message>
        <source>Detect closes the connection to %1 and then tries each device family on %2. Nothing is written to a device; your edits stay. Go on?</source>
        <translation>Die Suche trennt die Verbindung zu %1 und versucht dann jede Gerätefamilie an %2. Auf kein Gerät wird geschrieben; Ihre Änderungen bleiben. Fortfahren?</translation>
    </message>
    <message>
        <source>Detecting on %1…</source>
        <translation>Suche an %1…</translation>
    </message>
    <message>
        <source>Detect device on %1</source>
        <translation>Gerät an %1 suchen</translation>
    </message>
    <message>
        <source>Detect could not use the port: %1</source>
        <translation>Die Suche konnte die Schnittstelle nicht nutzen: %1</translation>
    </message>
    <message>
        <source>Found on %1: %2. The protocol and baud rate are filled in; press Connect to work with it.</source>
        <translation>Gefunden an %1: %2. Protokoll und Baudrate sind eingetragen; drücken Sie Verbinden, um damit zu arbeiten.</translation>
    </message>
    <message>
        <source>Detect: %1</source>
        <translation>Suche: %1</translation>
    </message>
    <message>
        <source>Detect was cancelled; nothing answered on %1 so far. Tried:</source>
        <translation>Die Suche wurde abgebrochen; bis dahin hat an %1 nichts geantwortet. Versucht:</translation>
    </message>
    <message>
        <source>Nothing answered on %1. Tried:</source>
        <translation>An %1 hat nichts geantwortet. Versucht:</translation>
    </message>
    <message>
        <source>Check the cable, the device&apos;s power and its interface settings (for an RS485 bus also the device number), then Detect again.</source>
        <translation>Prüfen Sie Kabel, Stromversorgung des Geräts und seine Schnittstelleneinstellungen (bei einem RS485-Bus auch die Gerätenummer) und suchen Sie dann erneut.</translation>
    </message>
    <message>
        <source>Detect: nothing answered on %1</source>
        <translation>Suche: an %1 hat nichts geantwortet</translation>
    </message>
    <message>
        <source>the simulated device</source>
        <translation>dem simulierten Gerät</translation>
    </message>
    <message>
        <source>• %1, %2: no answer</source>
        <translation>• %1, %2: keine Antwort</translation>
    </message>
    <message>
        <source>You are working on the simulated demo device: no machine is attached, and nothing you write here reaches a real device. To work on a machine, choose its port below (or type it: /dev/ttyUSB0, COM3, tcp://host:port), the protocol and the baud rate, then press Connect.</source>
        <translation>Sie arbeiten mit dem simulierten Demo-Gerät: Es ist keine Maschine angeschlossen, und nichts, was Sie hier schreiben, erreicht ein echtes Gerät. Um an einer Maschine zu arbeiten, wählen Sie unten ihre Schnittstelle (oder tippen Sie sie ein: /dev/ttyUSB0, COM3, tcp://Host:Port), das Protokoll und die Baudrate und drücken Sie dann „Verbinden“.</translation>
    </message>
    <message>
        <source>Ask every device number of a bus for an answer, or identify the one device of a point-to-point line.</source>
        <translation>Jede Gerätenummer eines Busses nach einer Antwort fragen oder das eine Gerät einer Punkt-zu-Punkt-Leitung erkennen.</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>nicht verbunden</translation>
    </message>
    <message>
        <source>Identifying the device failed: %1</source>
        <translation>Das Gerät wurde nicht erkannt: %1</translation>
    </message>
    <message>
        <source>%1, device number %2</source>
        <translation>%1, Gerätenummer %2</translation>
    </message>
    <message>
        <source>Reconnect to reach device %1.</source>
        <translation>Neu verbinden, um Gerät %1 zu erreichen.</translation>
    </message>
    <message>
        <source>%1, address %2</source>
        <translation>%1, Adresse %2</translation>
    </message>
    <message>
        <source>Switch to device %1</source>
        <translation>Zu Gerät %1 wechseln</translation>
    </message>
    <message>
        <source>Device %1 does not answer on the bus; device %2 does (the bus has %3): CamBench talks to device %2 now.</source>
        <translation>Gerät %1 antwortet nicht auf dem Bus; Gerät %2 antwortet (der Bus hat %3): CamBench spricht jetzt mit Gerät %2.</translation>
    </message>
</context>
<context>
    <name>cambench::ConnectionStrip</name>
    <message>
        <source>Reconnect now</source>
        <translation>Jetzt neu verbinden</translation>
    </message>
    <message>
        <source>The connection to %1 is lost.</source>
        <translation>Die Verbindung zu %1 ist unterbrochen.</translation>
    </message>
    <message>
        <source>CamBench tries again by itself; your edits are kept.</source>
        <translation>CamBench versucht es selbst erneut; Ihre Änderungen bleiben erhalten.</translation>
    </message>
    <message>
        <source>The device on %1 has not answered since %2.</source>
        <translation>Das Gerät an %1 antwortet seit %2 nicht mehr.</translation>
    </message>
    <message>
        <source>Live values are from then. Check the cable and the device&apos;s power; your edits are kept.</source>
        <translation>Die Live-Werte sind von diesem Zeitpunkt. Prüfen Sie Kabel und Stromversorgung des Geräts; Ihre Änderungen bleiben erhalten.</translation>
    </message>
    <message>
        <source>%1; identity not read yet.</source>
        <translation>%1; Kennung noch nicht gelesen.</translation>
    </message>
    <message>
        <source>Offline. What you edit stays on this PC until you connect and write it.</source>
        <translation>Offline. Was Sie bearbeiten, bleibt auf diesem PC, bis Sie sich verbinden und es schreiben.</translation>
    </message>
    <message>
        <source>Not connected to %1: %2</source>
        <translation>Nicht verbunden mit %1: %2</translation>
    </message>
    <message>
        <source>(no port given)</source>
        <translation>(keine Schnittstelle angegeben)</translation>
    </message>
    <message>
        <source>Check the port, the cable and the device&apos;s power, then connect again; your edits are kept.</source>
        <translation>Prüfen Sie Schnittstelle, Kabel und Stromversorgung des Geräts und verbinden Sie dann erneut; Ihre Änderungen bleiben erhalten.</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Check that the port and the protocol are this device&apos;s; nothing is written to it. Your edits are kept.</source>
        <translation>Prüfen Sie, ob Schnittstelle und Protokoll die dieses Geräts sind; es wird nichts hineingeschrieben. Ihre Änderungen bleiben erhalten.</translation>
    </message>
</context>
<context>
    <name>cambench::DeadTimeModesPage</name>
    <message>
        <source>Dead-time modes</source>
        <translation>Totzeit-Modi</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Ausgang</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Modus</translation>
    </message>
    <message>
        <source>Dead time (ms)</source>
        <translation>Totzeit (ms)</translation>
    </message>
    <message>
        <source>Switch-on (ms)</source>
        <translation>Einschalten (ms)</translation>
    </message>
    <message>
        <source>Switch-off / time (ms)</source>
        <translation>Ausschalten / Zeit (ms)</translation>
    </message>
    <message>
        <source>Normal: one dead time moves both switching points. On/off: the switch-on and the switch-off point each have their own. Path-time: the output switches on early by the switch-on dead time and stays on for the switching time.</source>
        <translation>Normal: eine Totzeit verschiebt beide Schaltpunkte. Ein/Aus: Einschalt- und Ausschaltpunkt haben je eine eigene. Weg-Zeit: der Ausgang schaltet um die Einschalttotzeit früher ein und bleibt für die Schaltzeit eingeschaltet.</translation>
    </message>
    <message>
        <source>Reading dead-time modes…</source>
        <translation>Totzeit-Modi werden gelesen…</translation>
    </message>
    <message>
        <source>Read dead-time modes</source>
        <translation>Totzeit-Modi lesen</translation>
    </message>
    <message>
        <source>Reading dead-time modes failed: %1</source>
        <translation>Lesen der Totzeit-Modi fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Dead-time modes read.</source>
        <translation>Totzeit-Modi gelesen.</translation>
    </message>
    <message>
        <source>Normal</source>
        <translation>Normal</translation>
    </message>
    <message>
        <source>On/off</source>
        <translation>Ein/Aus</translation>
    </message>
    <message>
        <source>Path-time</source>
        <translation>Weg-Zeit</translation>
    </message>
    <message>
        <source>Output %1 dead-time mode</source>
        <translation>Totzeit-Modus von Ausgang %1</translation>
    </message>
    <message>
        <source>Not read from the device yet.</source>
        <translation>Noch nicht aus dem Gerät gelesen.</translation>
    </message>
    <message>
        <source>On the device: %1</source>
        <translation>Im Gerät: %1</translation>
    </message>
    <message>
        <source>Edited, not written to the device</source>
        <translation>Geändert, nicht ins Gerät geschrieben</translation>
    </message>
    <message>
        <source>Largest dead time: %1</source>
        <translation>Größte Totzeit: %1</translation>
    </message>
    <message>
        <source>Not read from this device yet.</source>
        <translation>Noch nicht von diesem Gerät gelesen.</translation>
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
        <source>The dead time makes an output switch earlier by the time its actuator needs, at every speed. It belongs to the output, not to a program.</source>
        <translation>Die Totzeit lässt einen Ausgang um die Zeit früher schalten, die sein Stellglied braucht, bei jeder Geschwindigkeit. Sie gehört zum Ausgang, nicht zu einem Programm.</translation>
    </message>
    <message>
        <source>Dead times</source>
        <translation>Totzeiten</translation>
    </message>
    <message>
        <source>Reading dead times…</source>
        <translation>Totzeiten werden gelesen…</translation>
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
        <source>0.1 ms steps, at most %1 (the device&apos;s maximum)</source>
        <translation>Schritte von 0,1 ms, höchstens %1 (das Maximum des Geräts)</translation>
    </message>
</context>
<context>
    <name>cambench::DeviceChange</name>
    <message>
        <source>Program %1, output %2: %3 (read from %4: %5)</source>
        <translation>Programm %1, Ausgang %2: %3 (gelesen von %4: %5)</translation>
    </message>
    <message>
        <source>Program %1, output %2: %3 (not read from a device)</source>
        <translation>Programm %1, Ausgang %2: %3 (von keinem Gerät gelesen)</translation>
    </message>
    <message>
        <source>Program %1 name: &quot;%2&quot;</source>
        <translation>Name von Programm %1: „%2“</translation>
    </message>
    <message>
        <source>Output %1 name: &quot;%2&quot;</source>
        <translation>Name von Ausgang %1: „%2“</translation>
    </message>
    <message>
        <source>Output %1 dead time: %2 ms</source>
        <translation>Totzeit von Ausgang %1: %2 ms</translation>
    </message>
    <message>
        <source>Setting: %1</source>
        <translation>Einstellung: %1</translation>
    </message>
    <message>
        <source>Users: %1 changed</source>
        <translation>Benutzer: %1 geändert</translation>
    </message>
    <message>
        <source>PLC network %1</source>
        <translation>SPS-Netzwerk %1</translation>
    </message>
    <message>
        <source>Output %1 dead-time mode</source>
        <translation>Totzeitmodus von Ausgang %1</translation>
    </message>
    <message>
        <source>Analogue output %1 cams</source>
        <translation>Nocken von Analogausgang %1</translation>
    </message>
    <message>
        <source>Programming program</source>
        <translation>Programmierprogramm</translation>
    </message>
    <message>
        <source>EEPROM lock</source>
        <translation>EEPROM-Sperre</translation>
    </message>
    <message>
        <source>CamCon %1, device %2, %3 cams programmed</source>
        <translation>CamCon %1, Gerät %2, %3 Nocken programmiert</translation>
    </message>
    <message>
        <source>the device</source>
        <translation>dem Gerät</translation>
    </message>
</context>
<context>
    <name>cambench::DeviceChangeDialog</name>
    <message>
        <source>Another device answers</source>
        <translation>Ein anderes Gerät antwortet</translation>
    </message>
    <message>
        <source>Your changes:</source>
        <translation>Ihre Änderungen:</translation>
    </message>
    <message>
        <source>Another device answers.&lt;br&gt;New device, on the line now: &lt;b&gt;%1&lt;/b&gt;&lt;br&gt;Old device, the values shown were read from it: &lt;b&gt;%2&lt;/b&gt;&lt;br&gt;You changed %3 of those values. What shall the new device&apos;s values be?</source>
        <translation>Ein anderes Gerät antwortet.&lt;br&gt;Neues Gerät, jetzt an der Leitung: &lt;b&gt;%1&lt;/b&gt;&lt;br&gt;Altes Gerät, von ihm stammen die angezeigten Werte: &lt;b&gt;%2&lt;/b&gt;&lt;br&gt;Sie haben %3 dieser Werte geändert. Welche Werte soll das neue Gerät bekommen?</translation>
    </message>
    <message>
        <source>Take the new device&apos;s values (your changes are dropped)</source>
        <translation>Die Werte des neuen Geräts übernehmen (Ihre Änderungen werden verworfen)</translation>
    </message>
    <message>
        <source>Keep my changes, each applied to the new device&apos;s values</source>
        <translation>Meine Änderungen behalten, jede auf die Werte des neuen Geräts angewandt</translation>
    </message>
    <message>
        <source>Copy the old device&apos;s programs and sections (with your changes): written to the new device only when you write</source>
        <translation>Programme und Bereiche des alten Geräts kopieren (mit Ihren Änderungen): auf das neue Gerät geschrieben erst, wenn Sie schreiben</translation>
    </message>
</context>
<context>
    <name>cambench::DeviceChanges</name>
    <message>
        <source>%1: %2 → %3</source>
        <translation>%1: %2 → %3</translation>
    </message>
    <message>
        <source>Program %1, output %2</source>
        <translation>Programm %1, Ausgang %2</translation>
    </message>
    <message>
        <source>Program %1 name</source>
        <translation>Name von Programm %1</translation>
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
        <source>Users: the device&apos;s list of users changed.</source>
        <translation>Benutzer: die Benutzerliste des Geräts hat sich geändert.</translation>
    </message>
    <message>
        <source>PLC network %1 changed.</source>
        <translation>SPS-Netzwerk %1 hat sich geändert.</translation>
    </message>
</context>
<context>
    <name>cambench::DeviceCheck</name>
    <message>
        <source>Check which device answers</source>
        <translation>Prüfen, welches Gerät antwortet</translation>
    </message>
    <message>
        <source>Another device answers: nothing read from %1 is shown as this one&apos;s.</source>
        <translation>Ein anderes Gerät antwortet: nichts von %1 Gelesenes wird als Wert dieses Geräts gezeigt.</translation>
    </message>
    <message>
        <source>Your changes (%1) stay, not written yet.</source>
        <translation>Ihre Änderungen (%1) bleiben, noch nicht geschrieben.</translation>
    </message>
    <message>
        <source>A copy of that device&apos;s values waits to be written.</source>
        <translation>Eine Kopie der Werte jenes Geräts wartet darauf, geschrieben zu werden.</translation>
    </message>
</context>
<context>
    <name>cambench::DeviceReads</name>
    <message>
        <source>Not taken: your edits and the values shown are unchanged.</source>
        <translation>Nicht übernommen: Ihre Änderungen und die angezeigten Werte sind unverändert.</translation>
    </message>
    <message>
        <source>Read device identity</source>
        <translation>Gerätekennung lesen</translation>
    </message>
    <message>
        <source>Read program %1</source>
        <translation>Programm %1 lesen</translation>
    </message>
    <message>
        <source>Read names and dead times</source>
        <translation>Namen und Totzeiten lesen</translation>
    </message>
    <message>
        <source>Read settings</source>
        <translation>Einstellungen lesen</translation>
    </message>
    <message>
        <source>Read users</source>
        <translation>Benutzer lesen</translation>
    </message>
    <message>
        <source>Read PLC network</source>
        <translation>SPS-Netzwerk lesen</translation>
    </message>
    <message>
        <source>Read everything</source>
        <translation>Alles lesen</translation>
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
    <message>
        <source>Connect to %1</source>
        <translation>Verbinden mit %1</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>Trennen</translation>
    </message>
    <message>
        <source>No device identifies itself on the simulated line</source>
        <translation>Auf der simulierten Leitung meldet sich kein Gerät</translation>
    </message>
    <message>
        <source>No device identifies itself on %1</source>
        <translation>Auf %1 meldet sich kein Gerät</translation>
    </message>
    <message>
        <source>Checking which device answers on the simulated line…</source>
        <translation>Es wird geprüft, welches Gerät auf der simulierten Leitung antwortet…</translation>
    </message>
    <message>
        <source>Checking which device answers on %1…</source>
        <translation>Es wird geprüft, welches Gerät auf %1 antwortet…</translation>
    </message>
</context>
<context>
    <name>cambench::DeviceWriter</name>
    <message>
        <source>Write to the device</source>
        <translation>Ins Gerät schreiben</translation>
    </message>
    <message>
        <source>Nothing was written: the device on the line (CamCon %1, device number %2, %3 cams programmed) is not the one the values shown as on the device were read from (CamCon %4, device number %5, %6 cams programmed).
Read the device again or use Compare with device; your edits are kept.</source>
        <translation>Nichts wurde geschrieben: Das Gerät an der Leitung (CamCon %1, Gerätenummer %2, %3 Nocken programmiert) ist nicht das, von dem die als „auf dem Gerät“ gezeigten Werte gelesen wurden (CamCon %4, Gerätenummer %5, %6 Nocken programmiert).
Lesen Sie das Gerät neu oder verwenden Sie „Mit Gerät vergleichen“; Ihre Änderungen bleiben erhalten.</translation>
    </message>
    <message>
        <source>Nothing was written: the write was cancelled.</source>
        <translation>Nichts wurde geschrieben: das Schreiben wurde abgebrochen.</translation>
    </message>
    <message>
        <source>The write&apos;s report says nothing of this item: it counts as not written. Read the device to see what it holds.</source>
        <translation>Der Bericht des Schreibens sagt nichts über diesen Eintrag: Er gilt als nicht geschrieben. Lesen Sie das Gerät, um zu sehen, was es enthält.</translation>
    </message>
</context>
<context>
    <name>cambench::DialogStop</name>
    <message>
        <source>STOP (%1)</source>
        <translation>STOPP (%1)</translation>
    </message>
    <message>
        <source>Stops every axis and drive CamBench can reach, without a question. %1 does the same and closes this dialog.</source>
        <translation>Stoppt jede Achse und jeden Antrieb, die CamBench erreicht, ohne Rückfrage. %1 tut dasselbe und schließt diesen Dialog.</translation>
    </message>
    <message>
        <source>STOP sent…</source>
        <translation>STOPP gesendet…</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
</context>
<context>
    <name>cambench::EditsReplaced</name>
    <message>
        <source>Program %1, output %2: yours %3; the device now holds %4</source>
        <translation>Programm %1, Ausgang %2: Ihre %3; das Gerät enthält jetzt %4</translation>
    </message>
    <message>
        <source>Program %1, output %2: yours %3; the project holds %4</source>
        <translation>Programm %1, Ausgang %2: Ihre %3; das Projekt enthält %4</translation>
    </message>
    <message>
        <source>Output %1 dead time: yours %2 ms; the device now holds %3 ms</source>
        <translation>Totzeit Ausgang %1: Ihre %2 ms; das Gerät enthält jetzt %3 ms</translation>
    </message>
    <message>
        <source>Output %1 dead time: yours %2 ms; the project holds %3 ms</source>
        <translation>Totzeit Ausgang %1: Ihre %2 ms; das Projekt enthält %3 ms</translation>
    </message>
    <message>
        <source>Output %1 name: yours &quot;%2&quot;; the device now holds &quot;%3&quot;</source>
        <translation>Name Ausgang %1: Ihrer „%2“; das Gerät enthält jetzt „%3“</translation>
    </message>
    <message>
        <source>Output %1 name: yours &quot;%2&quot;; the project holds &quot;%3&quot;</source>
        <translation>Name Ausgang %1: Ihrer „%2“; das Projekt enthält „%3“</translation>
    </message>
</context>
<context>
    <name>cambench::EepromLockPage</name>
    <message>
        <source>EEPROM lock</source>
        <translation>EEPROM-Sperre</translation>
    </message>
    <message>
        <source>Lock the EEPROM</source>
        <translation>EEPROM sperren</translation>
    </message>
    <message>
        <source>Unlock the EEPROM</source>
        <translation>EEPROM entsperren</translation>
    </message>
    <message>
        <source>Writing the same values again and again (from a PLC, every cycle) wears the device&apos;s EEPROM out. Lock it first: changes then stay in RAM only. A complete deletion of the device unlocks it.</source>
        <translation>Werden dieselben Werte immer wieder geschrieben (von einer SPS, in jedem Zyklus), nutzt sich das EEPROM des Geräts ab. Sperren Sie es vorher: Änderungen bleiben dann nur im RAM. Ein vollständiges Löschen des Geräts hebt die Sperre auf.</translation>
    </message>
    <message>
        <source>Read the EEPROM lock</source>
        <translation>EEPROM-Sperre lesen</translation>
    </message>
    <message>
        <source>Reading the EEPROM lock failed: %1</source>
        <translation>Lesen der EEPROM-Sperre fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>State of the EEPROM lock: not read</source>
        <translation>Zustand der EEPROM-Sperre: nicht gelesen</translation>
    </message>
    <message>
        <source>The EEPROM is locked.</source>
        <translation>Das EEPROM ist gesperrt.</translation>
    </message>
    <message>
        <source>The EEPROM is not locked: changes are stored permanently.</source>
        <translation>Das EEPROM ist nicht gesperrt: Änderungen werden dauerhaft gespeichert.</translation>
    </message>
    <message>
        <source>Changes written now are kept in RAM only. They are lost when the device is switched off. Unlock the EEPROM to keep them.</source>
        <translation>Jetzt geschriebene Änderungen bleiben nur im RAM. Sie gehen verloren, wenn das Gerät ausgeschaltet wird. Entsperren Sie das EEPROM, um sie zu behalten.</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>The project wants the EEPROM locked; not written yet.</source>
        <translation>Das Projekt will das EEPROM gesperrt; noch nicht geschrieben.</translation>
    </message>
    <message>
        <source>The project wants the EEPROM unlocked; not written yet.</source>
        <translation>Das Projekt will das EEPROM entsperrt; noch nicht geschrieben.</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>nicht gelesen</translation>
    </message>
</context>
<context>
    <name>cambench::LineBackupDialog</name>
    <message>
        <source>Resume: skip devices already saved and verified in this folder</source>
        <translation>Fortsetzen: Geräte überspringen, die in diesem Ordner bereits gesichert und geprüft sind</translation>
    </message>
    <message>
        <source>Back up</source>
        <translation>Sichern</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Back up all devices on this line</source>
        <translation>Alle Geräte dieser Leitung sichern</translation>
    </message>
    <message>
        <source>empty: scan the line for devices 0 … 63</source>
        <translation>leer: Leitung nach Geräten 0 … 63 absuchen</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Durchsuchen…</translation>
    </message>
    <message>
        <source>Folder:</source>
        <translation>Ordner:</translation>
    </message>
    <message>
        <source>Devices:</source>
        <translation>Geräte:</translation>
    </message>
    <message>
        <source>Each device of the line is backed up into its own image in the folder, with a manifest of what was saved. A device that fails is noted and the others are still backed up.</source>
        <translation>Jedes Gerät der Leitung wird in ein eigenes Abbild im Ordner gesichert, mit einem Verzeichnis des Gesicherten. Ein Gerät, das fehlschlägt, wird vermerkt, und die anderen werden trotzdem gesichert.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a device number 0 … 63 (or given twice); write the numbers with commas, e.g. 0, 5, 7.</source>
        <translation>„%1“ ist keine Gerätenummer 0 … 63 (oder doppelt angegeben); schreiben Sie die Nummern mit Kommas, z. B. 0, 5, 7.</translation>
    </message>
    <message>
        <source>%1, %2, %3 baud</source>
        <translation>%1, %2, %3 Baud</translation>
    </message>
    <message>
        <source>waiting</source>
        <translation>wartet</translation>
    </message>
    <message>
        <source>Scanning the line…</source>
        <translation>Leitung wird abgesucht…</translation>
    </message>
    <message>
        <source>Backing up…</source>
        <translation>Wird gesichert…</translation>
    </message>
    <message>
        <source>Back up the line</source>
        <translation>Leitung sichern</translation>
    </message>
    <message>
        <source>Device %1</source>
        <translation>Gerät %1</translation>
    </message>
    <message>
        <source>Nothing was backed up: %1</source>
        <translation>Nichts wurde gesichert: %1</translation>
    </message>
    <message>
        <source>saved</source>
        <translation>gesichert</translation>
    </message>
    <message>
        <source>FAILED</source>
        <translation>FEHLGESCHLAGEN</translation>
    </message>
    <message>
        <source>Device %1: saved to %2.</source>
        <translation>Gerät %1: gesichert in %2.</translation>
    </message>
    <message>
        <source>Device %1: NOT saved: %2</source>
        <translation>Gerät %1: NICHT gesichert: %2</translation>
    </message>
    <message numerus="yes">
        <source>All %n device(s) saved into %1.</source>
        <translation>
            <numerusform>%n Gerät gesichert in %1.</numerusform>
            <numerusform>Alle %n Geräte gesichert in %1.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 of %2 devices saved; %3 NOT saved (see below). The manifest in %4 says the same.</source>
        <translation>%1 von %2 Geräten gesichert; %3 NICHT gesichert (siehe unten). Das Verzeichnis in %4 sagt dasselbe.</translation>
    </message>
</context>
<context>
    <name>cambench::LinkSettingsQuestion</name>
    <message>
        <source>Communication settings</source>
        <translation>Kommunikationseinstellungen</translation>
    </message>
    <message>
        <source>The values to write include communication settings: %1 (the device has %2).</source>
        <translation>Die zu schreibenden Werte enthalten Kommunikationseinstellungen: %1 (das Gerät hat %2).</translation>
    </message>
    <message>
        <source>others</source>
        <translation>andere</translation>
    </message>
    <message>
        <source>They decide how the device is reached. Written, the next connection to this device needs them: change the connection settings to match afterwards. Left out, the device keeps its own and everything else is written.</source>
        <translation>Sie bestimmen, wie das Gerät erreicht wird. Werden sie geschrieben, braucht die nächste Verbindung zu diesem Gerät sie: passen Sie danach die Verbindungseinstellungen an. Werden sie ausgelassen, behält das Gerät seine eigenen, und alles andere wird geschrieben.</translation>
    </message>
    <message>
        <source>Also write %1</source>
        <translation>Auch %1 schreiben</translation>
    </message>
    <message>
        <source>Write</source>
        <translation>Schreiben</translation>
    </message>
</context>
<context>
    <name>cambench::LiveDevicePage</name>
    <message>
        <source>STOP (Esc)</source>
        <translation>STOPP (Esc)</translation>
    </message>
</context>
<context>
    <name>cambench::LiveFamilyWindow</name>
    <message>
        <source>Connected: %1</source>
        <translation>Verbunden: %1</translation>
    </message>
</context>
<context>
    <name>cambench::LiveFreshness</name>
    <message>
        <source>No live values yet</source>
        <translation>Noch keine Live-Werte</translation>
    </message>
    <message>
        <source>Live, last answer %1</source>
        <translation>Live, letzte Antwort %1</translation>
    </message>
    <message>
        <source>No answer since %1</source>
        <translation>Keine Antwort seit %1</translation>
    </message>
    <message>
        <source>No answer yet</source>
        <translation>Noch keine Antwort</translation>
    </message>
    <message>
        <source>Not polled now; values of %1</source>
        <translation>Derzeit nicht abgefragt; Werte von %1</translation>
    </message>
    <message>
        <source>Paused (%1); values of %2</source>
        <translation>Pausiert (%1); Werte von %2</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>nicht gelesen</translation>
    </message>
    <message>
        <source>live</source>
        <translation>aktuell</translation>
    </message>
    <message>
        <source>no answer since %1</source>
        <translation>keine Antwort seit %1</translation>
    </message>
    <message>
        <source>no answer yet</source>
        <translation>noch keine Antwort</translation>
    </message>
    <message>
        <source>paused, read %1</source>
        <translation>pausiert, gelesen %1</translation>
    </message>
    <message>
        <source>paused (%1), read %2</source>
        <translation>pausiert (%1), gelesen %2</translation>
    </message>
</context>
<context>
    <name>cambench::Machine</name>
    <message>
        <source>The machine has a device named &quot;%1&quot; already; give this one another name.</source>
        <translation>Die Maschine hat schon ein Gerät namens „%1“; geben Sie diesem einen anderen Namen.</translation>
    </message>
</context>
<context>
    <name>cambench::MachineBackupRun</name>
    <message numerus="yes">
        <source>… and %n more (Details)</source>
        <translation>
            <numerusform>… und %n weiteres (Details)</numerusform>
            <numerusform>… und %n weitere (Details)</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 is not a machine backup folder: %2</source>
        <translation>%1 ist kein Maschinen-Sicherungsordner: %2</translation>
    </message>
    <message>
        <source>not in this backup</source>
        <translation>nicht in dieser Sicherung</translation>
    </message>
    <message>
        <source>not saved in this backup (%1)</source>
        <translation>nicht in dieser Sicherung gesichert (%1)</translation>
    </message>
    <message>
        <source>its file in the backup changed since it was saved</source>
        <translation>seine Datei in der Sicherung wurde seit dem Sichern verändert</translation>
    </message>
    <message>
        <source>Back up the machine</source>
        <translation>Maschine sichern</translation>
    </message>
    <message>
        <source>cannot make the folder %1; check the path and its rights</source>
        <translation>der Ordner %1 kann nicht angelegt werden; prüfen Sie den Pfad und seine Rechte</translation>
    </message>
    <message>
        <source>not saved: %1</source>
        <translation>nicht gesichert: %1</translation>
    </message>
    <message>
        <source>Back up %1</source>
        <translation>%1 sichern</translation>
    </message>
    <message>
        <source>failed: %1 - nothing was saved from it</source>
        <translation>fehlgeschlagen: %1 – nichts davon wurde gesichert</translation>
    </message>
    <message>
        <source>failed: %1</source>
        <translation>fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>saved: %1</source>
        <translation>gesichert: %1</translation>
    </message>
    <message>
        <source>NOT SAVED: %1</source>
        <translation>NICHT GESICHERT: %1</translation>
    </message>
    <message>
        <source>(the manifest: %1)</source>
        <translation>(das Verzeichnis: %1)</translation>
    </message>
    <message>
        <source>The machine file in %1 lacks the identities: %2</source>
        <translation>Der Maschinendatei in %1 fehlen die Identitäten: %2</translation>
    </message>
    <message>
        <source>Verify the machine</source>
        <translation>Maschine vergleichen</translation>
    </message>
    <message>
        <source>not verified: %1</source>
        <translation>nicht verglichen: %1</translation>
    </message>
    <message>
        <source>Verify %1</source>
        <translation>%1 vergleichen</translation>
    </message>
    <message>
        <source>%1 - not verified</source>
        <translation>%1 – nicht verglichen</translation>
    </message>
    <message numerus="yes">
        <source>equal: %n item(s) compared</source>
        <translation>
            <numerusform>gleich: %n Element verglichen</numerusform>
            <numerusform>gleich: %n Elemente verglichen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n difference(s):</source>
        <translation>
            <numerusform>%n Unterschied:</numerusform>
            <numerusform>%n Unterschiede:</numerusform>
        </translation>
    </message>
    <message>
        <source>Restore the machine</source>
        <translation>Maschine wiederherstellen</translation>
    </message>
    <message>
        <source>not restored: %1</source>
        <translation>nicht wiederhergestellt: %1</translation>
    </message>
    <message>
        <source>the backup of %1</source>
        <translation>die Sicherung von %1</translation>
    </message>
    <message>
        <source>Restore %1</source>
        <translation>%1 wiederherstellen</translation>
    </message>
    <message>
        <source>Plan the restore of %1</source>
        <translation>Wiederherstellung von %1 planen</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n item(s) to change</source>
        <translation>
            <numerusform>%1: %n Element zu ändern</numerusform>
            <numerusform>%1: %n Elemente zu ändern</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>plan read: %n item(s) to change</source>
        <translation>
            <numerusform>Plan gelesen: %n Element zu ändern</numerusform>
            <numerusform>Plan gelesen: %n Elemente zu ändern</numerusform>
        </translation>
    </message>
    <message>
        <source>Restore %1 from %2?</source>
        <translation>%1 aus %2 wiederherstellen?</translation>
    </message>
    <message>
        <source>What each device holds is saved beside the backup folder first. Then this is written:</source>
        <translation>Der Inhalt jedes Geräts wird zuerst neben dem Sicherungsordner gesichert. Dann wird dies geschrieben:</translation>
    </message>
    <message>
        <source>Restore</source>
        <translation>Wiederherstellung</translation>
    </message>
    <message>
        <source>not restored: cancelled, nothing was written</source>
        <translation>nicht wiederhergestellt: abgebrochen, nichts wurde geschrieben</translation>
    </message>
    <message>
        <source>not restored: cannot make the folder %1 for the safety copies; nothing was written</source>
        <translation>nicht wiederhergestellt: der Ordner %1 für die Sicherheitskopien kann nicht angelegt werden; nichts wurde geschrieben</translation>
    </message>
    <message>
        <source>restored: %1</source>
        <translation>wiederhergestellt: %1</translation>
    </message>
    <message>
        <source>NOT RESTORED completely: %1</source>
        <translation>NICHT vollständig WIEDERHERGESTELLT: %1</translation>
    </message>
    <message>
        <source>safety copies of a restore from %1</source>
        <translation>Sicherheitskopien einer Wiederherstellung aus %1</translation>
    </message>
    <message>
        <source>The safety copies in %1 are not listed: %2</source>
        <translation>Die Sicherheitskopien in %1 sind nicht aufgelistet: %2</translation>
    </message>
    <message>
        <source>What the devices held before: %1</source>
        <translation>Was die Geräte vorher enthielten: %1</translation>
    </message>
</context>
<context>
    <name>cambench::MachineHistoryDialog</name>
    <message>
        <source>equal</source>
        <translation>gleich</translation>
    </message>
    <message numerus="yes">
        <source>equal (%n change(s) of volatile items left out)</source>
        <translation>
            <numerusform>gleich (%n Änderung flüchtiger Elemente ausgelassen)</numerusform>
            <numerusform>gleich (%n Änderungen flüchtiger Elemente ausgelassen)</numerusform>
        </translation>
    </message>
    <message>
        <source>added: %1</source>
        <translation>hinzugefügt: %1</translation>
    </message>
    <message>
        <source>taken out of the machine</source>
        <translation>aus der Maschine genommen</translation>
    </message>
    <message>
        <source>NOT COMPARED: %1</source>
        <translation>NICHT VERGLICHEN: %1</translation>
    </message>
    <message>
        <source>&amp;Compare the two</source>
        <translation>Die beiden &amp;vergleichen</translation>
    </message>
    <message>
        <source>Compare with the devices &amp;now</source>
        <translation>Mit den Geräten &amp;jetzt vergleichen</translation>
    </message>
    <message>
        <source>&amp;Restore this version…</source>
        <translation>Diese Version &amp;wiederherstellen…</translation>
    </message>
    <message>
        <source>&amp;Mark as released</source>
        <translation>Als &amp;freigegeben markieren</translation>
    </message>
    <message>
        <source>History of %1 - %2</source>
        <translation>Verlauf von %1 – %2</translation>
    </message>
    <message>
        <source>Version</source>
        <translation>Version</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>Who</source>
        <translation>Wer</translation>
    </message>
    <message>
        <source>Why</source>
        <translation>Warum</translation>
    </message>
    <message>
        <source>Released</source>
        <translation>Freigegeben</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>Item</source>
        <translation>Element</translation>
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
        <source>Difference</source>
        <translation>Unterschied</translation>
    </message>
    <message>
        <source>released</source>
        <translation>freigegeben</translation>
    </message>
    <message>
        <source>%1 holds no version yet: Machine → Back up… into it, or `cambench-cli machine backup M.json --archive %1 -m WHY`.</source>
        <translation>%1 enthält noch keine Version: Maschine → Sichern… dorthinein oder `cambench-cli machine backup M.json --archive %1 -m WHY`.</translation>
    </message>
    <message>
        <source>machine file</source>
        <translation>Maschinendatei</translation>
    </message>
    <message>
        <source>%1: no difference.</source>
        <translation>%1: kein Unterschied.</translation>
    </message>
    <message>
        <source>%1: differences in %2.</source>
        <translation>%1: Unterschiede in %2.</translation>
    </message>
    <message>
        <source>the machine file</source>
        <translation>die Maschinendatei</translation>
    </message>
    <message>
        <source>Not every device was compared (see the table).</source>
        <translation>Nicht jedes Gerät wurde verglichen (siehe Tabelle).</translation>
    </message>
    <message>
        <source>Version %1 → %2</source>
        <translation>Version %1 → %2</translation>
    </message>
    <message>
        <source>Reading every device to compare it with version %1…</source>
        <translation>Jedes Gerät wird gelesen, um es mit Version %1 zu vergleichen…</translation>
    </message>
    <message>
        <source>Version %1 → the devices now</source>
        <translation>Version %1 → die Geräte jetzt</translation>
    </message>
    <message>
        <source>Version %1 is the released version now (%2).</source>
        <translation>Version %1 ist jetzt die freigegebene Version (%2).</translation>
    </message>
    <message>
        <source>Reading each device&apos;s plan of restoring version %1…</source>
        <translation>Der Plan jedes Geräts zum Wiederherstellen von Version %1 wird gelesen…</translation>
    </message>
    <message>
        <source>%1: NOT RESTORED: %2
</source>
        <translation>%1: NICHT WIEDERHERGESTELLT: %2
</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n item(s) to change
</source>
        <translation>
            <numerusform>%1: %n Element zu ändern
</numerusform>
            <numerusform>%1: %n Elemente zu ändern
</numerusform>
        </translation>
    </message>
    <message>
        <source>Version %1 is not restored: no device can take it.
%2</source>
        <translation>Version %1 wird nicht wiederhergestellt: kein Gerät kann sie übernehmen.
%2</translation>
    </message>
    <message>
        <source>Restore version %1</source>
        <translation>Version %1 wiederherstellen</translation>
    </message>
    <message>
        <source>Restore version %1 into %2? Each device&apos;s plan is in the details; a safety copy of what a device holds is taken first where its family takes one.</source>
        <translation>Version %1 in %2 wiederherstellen? Der Plan jedes Geräts steht in den Details; wo seine Familie eine anlegt, wird zuerst eine Sicherheitskopie des Inhalts eines Geräts angelegt.</translation>
    </message>
    <message>
        <source>Version %1 was not restored; nothing was written.</source>
        <translation>Version %1 wurde nicht wiederhergestellt; nichts wurde geschrieben.</translation>
    </message>
    <message>
        <source>Restore of version %1:
%2</source>
        <translation>Wiederherstellung von Version %1:
%2</translation>
    </message>
    <message>
        <source>The archive of %1</source>
        <translation>Das Archiv von %1</translation>
    </message>
    <message>
        <source>&amp;Draw the differences…</source>
        <translation>Unterschiede &amp;zeichnen…</translation>
    </message>
    <message>
        <source>version %1</source>
        <translation>Version %1</translation>
    </message>
    <message>
        <source>%1: %2 → %3</source>
        <translation>%1: %2 → %3</translation>
    </message>
    <message>
        <source>Drawn as well: %1 (Draw the differences…, or a double click on its row).</source>
        <translation>Auch gezeichnet: %1 (Unterschiede zeichnen… oder ein Doppelklick auf seine Zeile).</translation>
    </message>
    <message>
        <source>The device&apos;s changes between the two states compared (two versions, or a version and the devices now), drawn in its family&apos;s terms (a double click on its row does the same); a table is all there is for a family that draws none.</source>
        <translation>Die Änderungen des Geräts zwischen den beiden verglichenen Ständen (zwei Versionen oder eine Version und die Geräte jetzt), gezeichnet in den Begriffen seiner Gerätefamilie (ein Doppelklick auf seine Zeile tut dasselbe); für eine Gerätefamilie ohne Zeichnung gibt es nur die Tabelle.</translation>
    </message>
    <message>
        <source>the devices now</source>
        <translation>die Geräte jetzt</translation>
    </message>
</context>
<context>
    <name>cambench::MachineHistoryJobs</name>
    <message>
        <source>NOT RESTORED: cannot make the folder %1 for the safety copies; nothing was written.</source>
        <translation>NICHT WIEDERHERGESTELLT: der Ordner %1 für die Sicherheitskopien kann nicht angelegt werden; nichts wurde geschrieben.</translation>
    </message>
    <message>
        <source>NOT RESTORED: %1</source>
        <translation>NICHT WIEDERHERGESTELLT: %1</translation>
    </message>
    <message>
        <source>NOT RESTORED completely: %1</source>
        <translation>NICHT vollständig WIEDERHERGESTELLT: %1</translation>
    </message>
    <message>
        <source>restored</source>
        <translation>wiederhergestellt</translation>
    </message>
    <message>
        <source>not in this version of the machine</source>
        <translation>nicht in dieser Version der Maschine</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Nothing will be written to it.</source>
        <translation>Es wird nichts darauf geschrieben.</translation>
    </message>
    <message>
        <source>Nothing was written to it.</source>
        <translation>Es wurde nichts darauf geschrieben.</translation>
    </message>
    <message>
        <source>failed: no temporary folder for the backup now: %1</source>
        <translation>fehlgeschlagen: kein temporärer Ordner für die Sicherung jetzt: %1</translation>
    </message>
    <message>
        <source>%1: back up to compare</source>
        <translation>%1: sichern zum Vergleich</translation>
    </message>
    <message>
        <source>failed: %1</source>
        <translation>fehlgeschlagen: %1</translation>
    </message>
</context>
<context>
    <name>cambench::MachineReport</name>
    <message>
        <source>not identified</source>
        <translation>nicht erkannt</translation>
    </message>
    <message>
        <source>never</source>
        <translation>nie</translation>
    </message>
    <message>
        <source>Machine report: %1</source>
        <translation>Maschinenbericht: %1</translation>
    </message>
    <message>
        <source>Made %1 by CamBench.</source>
        <translation>Erstellt am %1 von CamBench.</translation>
    </message>
    <message>
        <source>Machine file: %1</source>
        <translation>Maschinendatei: %1</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>Family</source>
        <translation>Familie</translation>
    </message>
    <message>
        <source>Port</source>
        <translation>Schnittstelle</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>Leitung</translation>
    </message>
    <message>
        <source>Identity</source>
        <translation>Identität</translation>
    </message>
    <message>
        <source>Not written</source>
        <translation>Nicht geschrieben</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Identity: %1</source>
        <translation>Identität: %1</translation>
    </message>
    <message>
        <source>Line: %1 on %2</source>
        <translation>Leitung: %1 an %2</translation>
    </message>
    <message>
        <source>Edits on this PC not written to the device: %1</source>
        <translation>Änderungen auf diesem PC, nicht ins Gerät geschrieben: %1</translation>
    </message>
    <message>
        <source>Machine report</source>
        <translation>Maschinenbericht</translation>
    </message>
    <message>
        <source>Page %1 of %2</source>
        <translation>Seite %1 von %2</translation>
    </message>
    <message>
        <source>Recorded identity: %1</source>
        <translation>Aufgezeichnete Identität: %1</translation>
    </message>
    <message>
        <source>Last answered: %1</source>
        <translation>Zuletzt geantwortet: %1</translation>
    </message>
    <message>
        <source>not read: %1; its section says what this PC holds.</source>
        <translation>nicht gelesen: %1; sein Abschnitt zeigt, was dieser PC enthält.</translation>
    </message>
    <message>
        <source>read</source>
        <translation>gelesen</translation>
    </message>
    <message>
        <source>not read: %1</source>
        <translation>nicht gelesen: %1</translation>
    </message>
</context>
<context>
    <name>cambench::MachineReportChanges</name>
    <message>
        <source>%1: version %2 of %3 by %4</source>
        <translation>%1: Version %2 vom %3 von %4</translation>
    </message>
    <message>
        <source>version %1</source>
        <translation>Version %1</translation>
    </message>
    <message>
        <source>equal to the released version</source>
        <translation>gleich der freigegebenen Version</translation>
    </message>
    <message numerus="yes">
        <source>equal to the released version (%n change(s) of volatile items left out)</source>
        <translation>
            <numerusform>gleich der freigegebenen Version (%n Änderung flüchtiger Werte nicht gezählt)</numerusform>
            <numerusform>gleich der freigegebenen Version (%n Änderungen flüchtiger Werte nicht gezählt)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>DIFFERS: %n difference(s)</source>
        <translation>
            <numerusform>UNTERSCHIEDLICH: %n Unterschied</numerusform>
            <numerusform>UNTERSCHIEDLICH: %n Unterschiede</numerusform>
        </translation>
    </message>
    <message>
        <source>not in the released version: not compared</source>
        <translation>nicht in der freigegebenen Version: nicht verglichen</translation>
    </message>
    <message>
        <source>in the released version, but no longer a device of this machine</source>
        <translation>in der freigegebenen Version, aber kein Gerät dieser Maschine mehr</translation>
    </message>
    <message>
        <source>NOT COMPARED: %1</source>
        <translation>NICHT VERGLICHEN: %1</translation>
    </message>
    <message>
        <source>Changes since the released version</source>
        <translation>Änderungen seit der freigegebenen Version</translation>
    </message>
    <message>
        <source>Not part of this report: no machine archive was chosen.</source>
        <translation>Nicht Teil dieses Protokolls: Es wurde kein Maschinenarchiv gewählt.</translation>
    </message>
    <message>
        <source>Archive: %1</source>
        <translation>Archiv: %1</translation>
    </message>
    <message>
        <source>Nothing was compared: %1</source>
        <translation>Nichts wurde verglichen: %1</translation>
    </message>
    <message>
        <source>Released version: %1</source>
        <translation>Freigegebene Version: %1</translation>
    </message>
    <message>
        <source>Each device was read for this report and compared with its backup in that version.</source>
        <translation>Jedes Gerät wurde für dieses Protokoll gelesen und mit seiner Sicherung in dieser Version verglichen.</translation>
    </message>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>Since the released version</source>
        <translation>Seit der freigegebenen Version</translation>
    </message>
</context>
<context>
    <name>cambench::MachineStop</name>
    <message>
        <source>not connected: the STOP was not sent</source>
        <translation>nicht verbunden: der STOP wurde nicht gesendet</translation>
    </message>
    <message>
        <source>acknowledged by %1</source>
        <translation>quittiert von %1</translation>
    </message>
    <message>
        <source>NOT acknowledged by %1 – use the machine&apos;s emergency stop</source>
        <translation>NICHT quittiert von %1 – benutzen Sie den Not-Halt der Maschine</translation>
    </message>
    <message>
        <source>could not reach %1 – use the machine&apos;s emergency stop</source>
        <translation>%1 nicht erreicht – benutzen Sie den Not-Halt der Maschine</translation>
    </message>
</context>
<context>
    <name>cambench::MachineUnit</name>
    <message>
        <source>not opened: %1</source>
        <translation>nicht geöffnet: %1</translation>
    </message>
    <message>
        <source>connected</source>
        <translation>verbunden</translation>
    </message>
    <message>
        <source>connecting…</source>
        <translation>verbinde…</translation>
    </message>
    <message>
        <source>gone, retrying: %1</source>
        <translation>weg, neuer Versuch läuft: %1</translation>
    </message>
    <message>
        <source>not connected: %1</source>
        <translation>nicht verbunden: %1</translation>
    </message>
    <message>
        <source>not connected yet: choose its port on its Connection page</source>
        <translation>noch nicht verbunden: Schnittstelle auf seiner Seite Verbindung wählen</translation>
    </message>
    <message>
        <source>offline</source>
        <translation>offline</translation>
    </message>
    <message>
        <source>Watch the line</source>
        <translation>Leitung beobachten</translation>
    </message>
    <message>
        <source>the connect</source>
        <translation>dem Verbinden</translation>
    </message>
    <message>
        <source>Check which device answers</source>
        <translation>Prüfen, welches Gerät antwortet</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>nicht verbunden</translation>
    </message>
    <message>
        <source>another device answers: no %1 identifies itself (%2)</source>
        <translation>ein anderes Gerät antwortet: kein Gerät %1 meldet sich (%2)</translation>
    </message>
    <message>
        <source>no answer: %1</source>
        <translation>keine Antwort: %1</translation>
    </message>
    <message>
        <source>no answer since %1</source>
        <translation>keine Antwort seit %1</translation>
    </message>
    <message>
        <source>no answer since %1: %2</source>
        <translation>keine Antwort seit %1: %2</translation>
    </message>
    <message>
        <source>connected, %1</source>
        <translation>verbunden, %1</translation>
    </message>
    <message>
        <source>checking which device answers…</source>
        <translation>es wird geprüft, welches Gerät antwortet…</translation>
    </message>
    <message>
        <source>did not identify itself: %1</source>
        <translation>hat sich nicht gemeldet: %1</translation>
    </message>
</context>
<context>
    <name>cambench::MachineWindow</name>
    <message>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>Not written</source>
        <translation>Nicht geschrieben</translation>
    </message>
    <message>
        <source>Family</source>
        <translation>Familie</translation>
    </message>
    <message>
        <source>Port</source>
        <translation>Schnittstelle</translation>
    </message>
    <message>
        <source>STOP: %1</source>
        <translation>STOP: %1</translation>
    </message>
    <message>
        <source>&amp;Machine</source>
        <translation>&amp;Maschine</translation>
    </message>
    <message>
        <source>&amp;Add device…</source>
        <translation>Gerät &amp;hinzufügen…</translation>
    </message>
    <message>
        <source>&amp;Save machine as…</source>
        <translation>Maschine &amp;speichern unter…</translation>
    </message>
    <message>
        <source>Machine &amp;report…</source>
        <translation>Maschinen&amp;bericht…</translation>
    </message>
    <message>
        <source>&amp;Close machine</source>
        <translation>Maschine s&amp;chließen</translation>
    </message>
    <message>
        <source>%1: connection lost (%2); the other devices are not affected.</source>
        <translation>%1: Verbindung verloren (%2); die anderen Geräte sind nicht betroffen.</translation>
    </message>
    <message>
        <source>CamBench – machine %1</source>
        <translation>CamBench – Maschine %1</translation>
    </message>
    <message numerus="yes">
        <source>[%n change(s) not written]</source>
        <translation>
            <numerusform>[%n Änderung nicht geschrieben]</numerusform>
            <numerusform>[%n Änderungen nicht geschrieben]</numerusform>
        </translation>
    </message>
    <message>
        <source>Save machine</source>
        <translation>Maschine speichern</translation>
    </message>
    <message>
        <source>Machine file (*.json)</source>
        <translation>Maschinendatei (*.json)</translation>
    </message>
    <message>
        <source>Machine saved to %1.</source>
        <translation>Maschine in %1 gespeichert.</translation>
    </message>
    <message>
        <source>Machine report</source>
        <translation>Maschinenbericht</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Machine report written to %1.</source>
        <translation>Maschinenbericht in %1 geschrieben.</translation>
    </message>
    <message>
        <source>Add device</source>
        <translation>Gerät hinzufügen</translation>
    </message>
    <message>
        <source>Name of the device in this machine (e.g. feed):</source>
        <translation>Name des Geräts in dieser Maschine (z. B. vorschub):</translation>
    </message>
    <message>
        <source>%1: choose its port on its Connection page (Detect finds the protocol), then Connect.</source>
        <translation>%1: Schnittstelle auf seiner Seite Verbindung wählen (Gerät suchen findet das Protokoll), dann Verbinden.</translation>
    </message>
    <message>
        <source>&amp;Back up…</source>
        <translation>S&amp;ichern…</translation>
    </message>
    <message>
        <source>Back up the machine into</source>
        <translation>Maschine sichern in</translation>
    </message>
    <message>
        <source>Back up the machine</source>
        <translation>Maschine sichern</translation>
    </message>
    <message>
        <source>Why (kept in the backup&apos;s manifest):</source>
        <translation>Warum (wird im Verzeichnis der Sicherung festgehalten):</translation>
    </message>
    <message>
        <source>&amp;Verify…</source>
        <translation>&amp;Vergleichen…</translation>
    </message>
    <message>
        <source>Verify against the backup</source>
        <translation>Mit der Sicherung vergleichen</translation>
    </message>
    <message>
        <source>R&amp;estore…</source>
        <translation>&amp;Wiederherstellen…</translation>
    </message>
    <message>
        <source>Restore the backup</source>
        <translation>Sicherung wiederherstellen</translation>
    </message>
    <message>
        <source>&amp;History…</source>
        <translation>Verl&amp;auf…</translation>
    </message>
    <message>
        <source>Add the changes since the released version? Each device is then compared with its backup in the version released in the machine&apos;s archive.</source>
        <translation>Die Änderungen seit der freigegebenen Version hinzufügen? Jedes Gerät wird dann mit seiner Sicherung in der Version verglichen, die im Archiv der Maschine freigegeben ist.</translation>
    </message>
    <message>
        <source>Choose the archive…</source>
        <translation>Archiv wählen…</translation>
    </message>
    <message>
        <source>Without</source>
        <translation>Ohne</translation>
    </message>
    <message>
        <source>The archive of %1</source>
        <translation>Das Archiv von %1</translation>
    </message>
    <message>
        <source>not compared: %1</source>
        <translation>nicht verglichen: %1</translation>
    </message>
</context>
<context>
    <name>cambench::MainWindow</name>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
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
        <source>CamBench – %1</source>
        <translation>CamBench – %1</translation>
    </message>
    <message numerus="yes">
        <source>[%n change(s) not written]</source>
        <translation>
            <numerusform>[%n Änderung nicht geschrieben]</numerusform>
            <numerusform>[%n Änderungen nicht geschrieben]</numerusform>
        </translation>
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
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Cancel what the device is doing for you now.</source>
        <translation>Abbrechen, was das Gerät gerade für Sie tut.</translation>
    </message>
    <message>
        <source>&amp;Last write report…</source>
        <translation>&amp;Letzter Schreibbericht…</translation>
    </message>
    <message>
        <source>Last write (%1): complete</source>
        <translation>Letztes Schreiben (%1): vollständig</translation>
    </message>
    <message>
        <source>Last write (%1): NOT complete</source>
        <translation>Letztes Schreiben (%1): NICHT vollständig</translation>
    </message>
    <message>
        <source>Show the report of the last write: %1</source>
        <translation>Bericht des letzten Schreibens zeigen: %1</translation>
    </message>
    <message>
        <source>%1 (written at %2)</source>
        <translation>%1 (geschrieben um %2)</translation>
    </message>
    <message>
        <source>Identify device</source>
        <translation>Gerät erkennen</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>nicht verbunden</translation>
    </message>
    <message>
        <source>Connected: %1</source>
        <translation>Verbunden: %1</translation>
    </message>
    <message>
        <source>The device did not identify itself: %1</source>
        <translation>Das Gerät hat sich nicht identifiziert: %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;CamBench %1&lt;/b&gt;&lt;p&gt;Programming, monitoring and backup of machine controllers: %2.&lt;/p&gt;</source>
        <translation>&lt;b&gt;CamBench %1&lt;/b&gt;&lt;p&gt;Programmieren, Beobachten und Sichern von Maschinensteuerungen: %2.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>CamBench</source>
        <translation>CamBench</translation>
    </message>
    <message>
        <source>No page of CamBench knows the devices of this protocol.</source>
        <translation>Keine Seite von CamBench kennt die Geräte dieses Protokolls.</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>&amp;Werkzeuge</translation>
    </message>
    <message>
        <source>Connection re-established: the same device answers. Your edits are unchanged; Compare with device reads what the device holds now.</source>
        <translation>Verbindung wiederhergestellt: dasselbe Gerät antwortet. Ihre Bearbeitungen sind unverändert; Mit Gerät vergleichen liest, was das Gerät jetzt enthält.</translation>
    </message>
    <message>
        <source>Connection re-established, but another device answers on this port: see the note at the top.</source>
        <translation>Verbindung wiederhergestellt, aber an diesem Anschluss antwortet ein anderes Gerät: siehe den Hinweis oben.</translation>
    </message>
    <message>
        <source>&amp;Check this device…</source>
        <translation>Dieses Gerät &amp;prüfen…</translation>
    </message>
    <message>
        <source>Quit</source>
        <translation>Beenden</translation>
    </message>
    <message>
        <source>Stops every axis and drive of every device of the machine, without a question. %1 does the same from every page.</source>
        <translation>Stoppt jede Achse und jeden Antrieb jedes Geräts der Maschine, ohne Rückfrage. %1 tut dasselbe auf jeder Seite.</translation>
    </message>
    <message>
        <source>Open &amp;machine…</source>
        <translation>&amp;Maschine öffnen…</translation>
    </message>
    <message>
        <source>New mac&amp;hine…</source>
        <translation>Neue Masc&amp;hine…</translation>
    </message>
    <message>
        <source>Open &amp;demo machine</source>
        <translation>&amp;Demo-Maschine öffnen</translation>
    </message>
</context>
<context>
    <name>cambench::Mc1AxesPage</name>
    <message>
        <source>Axes</source>
        <translation>Achsen</translation>
    </message>
    <message>
        <source>Axis </source>
        <translation>Achse </translation>
    </message>
    <message>
        <source>Move (each asks first)</source>
        <translation>Verfahren (jede Bewegung fragt vorher)</translation>
    </message>
    <message>
        <source>Home</source>
        <translation>Referenzfahrt</translation>
    </message>
    <message>
        <source>Jog −</source>
        <translation>Tippen −</translation>
    </message>
    <message>
        <source>Jog +</source>
        <translation>Tippen +</translation>
    </message>
    <message>
        <source>Move to</source>
        <translation>Fahren nach</translation>
    </message>
    <message>
        <source>Move by</source>
        <translation>Fahren um</translation>
    </message>
    <message>
        <source>Set speed</source>
        <translation>Geschwindigkeit setzen</translation>
    </message>
    <message>
        <source>Acknowledge error</source>
        <translation>Fehler quittieren</translation>
    </message>
    <message>
        <source>The %1 has no axis telegrams: moving axes needs an MC200 V2.</source>
        <translation>Die %1 hat keine Achstelegramme: Achsen verfahren braucht eine MC200 V2.</translation>
    </message>
    <message>
        <source>Not connected to an MC100/MC200.</source>
        <translation>Nicht mit einer MC100/MC200 verbunden.</translation>
    </message>
    <message>
        <source>homed</source>
        <translation>referenziert</translation>
    </message>
    <message>
        <source>not homed</source>
        <translation>nicht referenziert</translation>
    </message>
    <message>
        <source>axis error</source>
        <translation>Achsfehler</translation>
    </message>
    <message>
        <source>no error</source>
        <translation>kein Fehler</translation>
    </message>
    <message>
        <source>Read axis</source>
        <translation>Achse lesen</translation>
    </message>
    <message>
        <source>The axis moves until STOP (or Escape) is pressed.</source>
        <translation>Die Achse fährt, bis STOPP (oder Escape) gedrückt wird.</translation>
    </message>
    <message>
        <source>The axis moves at its set speed. STOP (or Escape) stops it.</source>
        <translation>Die Achse fährt mit ihrer eingestellten Geschwindigkeit. STOPP (oder Escape) hält sie an.</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Verfahren</translation>
    </message>
    <message>
        <source>%1 on the %2?</source>
        <translation>%2: %1?</translation>
    </message>
    <message>
        <source>Axis command</source>
        <translation>Achsbefehl</translation>
    </message>
    <message>
        <source>Stops every axis and drops what waits for the line: the STOP above every page. Escape does the same.</source>
        <translation>Stoppt jede Achse und verwirft, was auf die Leitung wartet: der STOPP über jeder Seite. Escape tut dasselbe.</translation>
    </message>
    <message>
        <source>Moves are off while the STOP cannot reach the %1.</source>
        <translation>Verfahren ist gesperrt, solange der STOPP %1 nicht erreicht.</translation>
    </message>
    <message>
        <source>axis %1 is jogging %2 (now at %3)</source>
        <translation>Achse %1 tippt %2 (jetzt bei %3)</translation>
    </message>
    <message>
        <source>Find axes</source>
        <translation>Achsen suchen</translation>
    </message>
    <message>
        <source>Which axes the controller has could not be read: %1</source>
        <translation>Welche Achsen die Steuerung hat, war nicht lesbar: %1</translation>
    </message>
    <message>
        <source>The controller has no axes (%1).</source>
        <translation>Die Steuerung hat keine Achsen (%1).</translation>
    </message>
    <message>
        <source>Axes %1 (%2).</source>
        <translation>Achsen %1 (%2).</translation>
    </message>
    <message>
        <source>Position %1 · %2 · %3 · %4</source>
        <translation>Position %1 · %2 · %3 · %4</translation>
    </message>
    <message>
        <source>jogging %1</source>
        <translation>tippt %1</translation>
    </message>
    <message>
        <source>target %1</source>
        <translation>Ziel %1</translation>
    </message>
    <message>
        <source>Not read: %1</source>
        <translation>Nicht gelesen: %1</translation>
    </message>
    <message>
        <source>Done: %1 (the controller acknowledged it). Now %2.</source>
        <translation>Erledigt: %1 (die Steuerung hat es quittiert). Jetzt %2.</translation>
    </message>
    <message>
        <source>Set the speed of axis %1 to %2 on the %3?</source>
        <translation>%3: Geschwindigkeit der Achse %1 auf %2 setzen?</translation>
    </message>
    <message>
        <source>The controller moves the axis at this speed from now on.</source>
        <translation>Die Steuerung fährt die Achse ab jetzt mit dieser Geschwindigkeit.</translation>
    </message>
</context>
<context>
    <name>cambench::Mc1AxisParametersBox</name>
    <message>
        <source>Load parameter table…</source>
        <translation>Parametertabelle laden…</translation>
    </message>
    <message>
        <source>A CSV file of name,axis,parameter lines (name: position, target or status) from the controller&apos;s MC-1B manual: the RDSTAT parameter numbers of its axes.</source>
        <translation>Eine CSV-Datei mit Zeilen name,axis,parameter (name: position, target oder status) aus dem MC-1B-Handbuch der Steuerung: die RDSTAT-Parameternummern ihrer Achsen.</translation>
    </message>
    <message>
        <source>Load parameter table</source>
        <translation>Parametertabelle laden</translation>
    </message>
    <message>
        <source>CSV files (*.csv *.txt);;All files (*)</source>
        <translation>CSV-Dateien (*.csv *.txt);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>%1 was not loaded: %2
The table in use stays: %3</source>
        <translation>%1 wurde nicht geladen: %2
Die verwendete Tabelle bleibt: %3</translation>
    </message>
    <message>
        <source>The table loaded last (%1) could not be read again: %2</source>
        <translation>Die zuletzt geladene Tabelle (%1) ließ sich nicht erneut lesen: %2</translation>
    </message>
    <message>
        <source>Use parameter table</source>
        <translation>Parametertabelle verwenden</translation>
    </message>
    <message>
        <source>Axis parameter numbers: provisional (%1). Positions and states read through them are not facts: load the controller&apos;s parameter table.</source>
        <translation>Achsparameternummern: vorläufig (%1). Damit gelesene Positionen und Zustände sind keine Tatsachen: laden Sie die Parametertabelle der Steuerung.</translation>
    </message>
    <message>
        <source>Axis parameter numbers: from %1.</source>
        <translation>Achsparameternummern: aus %1.</translation>
    </message>
</context>
<context>
    <name>cambench::Mc1MemoryPage</name>
    <message>
        <source>Memory</source>
        <translation>Speicher</translation>
    </message>
    <message>
        <source>bytes in hex, e.g. 0a 0b 0c</source>
        <translation>Bytes hexadezimal, z. B. 0a 0b 0c</translation>
    </message>
    <message>
        <source>Read</source>
        <translation>Lesen</translation>
    </message>
    <message>
        <source>Write…</source>
        <translation>Schreiben…</translation>
    </message>
    <message>
        <source>Address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <source>bytes</source>
        <translation>Bytes</translation>
    </message>
    <message>
        <source>Write (MC200 V2; asks first, then reads back)</source>
        <translation>Schreiben (MC200 V2; fragt vorher, liest danach zurück)</translation>
    </message>
    <message>
        <source>Write the bytes as pairs of hex digits, e.g. 0a 0b 0c.</source>
        <translation>Schreiben Sie die Bytes als Paare von Hexadezimalziffern, z. B. 0a 0b 0c.</translation>
    </message>
    <message>
        <source>The %1 has no memory telegrams (an MC200 has).</source>
        <translation>Die %1 hat keine Speichertelegramme (eine MC200 hat sie).</translation>
    </message>
    <message>
        <source>Read memory</source>
        <translation>Speicher lesen</translation>
    </message>
    <message>
        <source>%1 bytes read from 0x%2 at %3.</source>
        <translation>%1 Bytes ab 0x%2 um %3 gelesen.</translation>
    </message>
    <message>
        <source>Write</source>
        <translation>Schreiben</translation>
    </message>
    <message numerus="yes">
        <source>Write %n byte(s) at %1 of the %2?</source>
        <translation>
            <numerusform>%n Byte an %1 der %2 schreiben?</numerusform>
            <numerusform>%n Bytes an %1 der %2 schreiben?</numerusform>
        </translation>
    </message>
    <message>
        <source>The controller uses its memory at once; a wrong byte can stop its program.</source>
        <translation>Die Steuerung verwendet ihren Speicher sofort; ein falsches Byte kann ihr Programm anhalten.</translation>
    </message>
    <message>
        <source>Write memory</source>
        <translation>Speicher schreiben</translation>
    </message>
    <message>
        <source>Written at %1 and read back.</source>
        <translation>An %1 geschrieben und zurückgelesen.</translation>
    </message>
    <message>
        <source>Written at %1, but the bytes read back differ.</source>
        <translation>An %1 geschrieben, aber die zurückgelesenen Bytes weichen ab.</translation>
    </message>
</context>
<context>
    <name>cambench::Mc1Page</name>
    <message>
        <source>Done: %1 (the controller acknowledged it). Reading back failed: %2</source>
        <translation>Erledigt: %1 (die Steuerung hat es quittiert). Das Zurücklesen ist fehlgeschlagen: %2</translation>
    </message>
</context>
<context>
    <name>cambench::Mc1PointsPage</name>
    <message>
        <source>Flags &amp; I/O</source>
        <translation>Merker &amp; E/A</translation>
    </message>
    <message>
        <source>Inputs (E)</source>
        <translation>Eingänge (E)</translation>
    </message>
    <message>
        <source>Outputs (A) - click to set or clear</source>
        <translation>Ausgänge (A) – Klick setzt oder löscht</translation>
    </message>
    <message>
        <source>Flags (M) - click to set or clear</source>
        <translation>Merker (M) – Klick setzt oder löscht</translation>
    </message>
    <message>
        <source>From</source>
        <translation>Von</translation>
    </message>
    <message>
        <source>count</source>
        <translation>Anzahl</translation>
    </message>
    <message>
        <source>Read flags and I/O</source>
        <translation>Merker und E/A lesen</translation>
    </message>
    <message>
        <source>Set %1 on the %2?</source>
        <translation>%1 an der %2 setzen?</translation>
    </message>
    <message>
        <source>Clear %1 on the %2?</source>
        <translation>%1 an der %2 löschen?</translation>
    </message>
    <message>
        <source>The output switches at once; whatever it drives on the machine acts.</source>
        <translation>Der Ausgang schaltet sofort; was er an der Maschine ansteuert, reagiert.</translation>
    </message>
    <message>
        <source>The PLC program sees the flag at once.</source>
        <translation>Das SPS-Programm sieht den Merker sofort.</translation>
    </message>
    <message>
        <source>Set</source>
        <translation>Setzen</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <source>Write flag or output</source>
        <translation>Merker oder Ausgang schreiben</translation>
    </message>
    <message>
        <source>%1 = %2, read back.</source>
        <translation>%1 = %2, zurückgelesen.</translation>
    </message>
    <message>
        <source>%1 reads back %2 after the write.</source>
        <translation>%1 liest nach dem Schreiben %2 zurück.</translation>
    </message>
</context>
<context>
    <name>cambench::Mc1ProgramPage</name>
    <message>
        <source>Program</source>
        <translation>Programm</translation>
    </message>
    <message>
        <source>The PLC program runs: outputs and axes follow it.</source>
        <translation>Das SPS-Programm läuft: Ausgänge und Achsen folgen ihm.</translation>
    </message>
    <message>
        <source>The PLC program stops where it is; outputs keep their state.</source>
        <translation>Das SPS-Programm hält an, wo es ist; Ausgänge behalten ihren Zustand.</translation>
    </message>
    <message>
        <source>One instruction of the PLC program runs; it may switch an output or start an axis.</source>
        <translation>Eine Anweisung des SPS-Programms läuft; sie kann einen Ausgang schalten oder eine Achse starten.</translation>
    </message>
    <message>
        <source>The controller restarts: axes stop, outputs drop, the PLC program starts again from the beginning.</source>
        <translation>Die Steuerung startet neu: Achsen halten an, Ausgänge fallen ab, das SPS-Programm beginnt von vorn.</translation>
    </message>
    <message>
        <source>The controller&apos;s flash is overwritten with what it holds now. What the flash held before is lost.</source>
        <translation>Der Flash der Steuerung wird mit ihrem jetzigen Inhalt überschrieben. Was der Flash vorher enthielt, geht verloren.</translation>
    </message>
    <message>
        <source>The controller&apos;s variables are replaced by those in its flash. Values changed since the last save are lost.</source>
        <translation>Die Variablen der Steuerung werden durch die im Flash ersetzt. Seit dem letzten Sichern geänderte Werte gehen verloren.</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
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
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <source>Reset…</source>
        <translation>Reset…</translation>
    </message>
    <message>
        <source>Save to flash…</source>
        <translation>In Flash sichern…</translation>
    </message>
    <message>
        <source>Load from flash…</source>
        <translation>Aus Flash laden…</translation>
    </message>
    <message>
        <source>The %1 has no program telegrams: status and control need an MC200 V2 (SYSDATA). Variables, flags and I/O work.</source>
        <translation>Die %1 hat keine Programmtelegramme: Status und Steuerung brauchen eine MC200 V2 (SYSDATA). Variablen, Merker und E/A funktionieren.</translation>
    </message>
    <message>
        <source>Not connected to an MC100/MC200.</source>
        <translation>Nicht mit einer MC100/MC200 verbunden.</translation>
    </message>
    <message>
        <source>PLC program: %1</source>
        <translation>SPS-Programm: %1</translation>
    </message>
    <message>
        <source>Read program status</source>
        <translation>Programmstatus lesen</translation>
    </message>
    <message>
        <source>%1 on the %2?</source>
        <translation>%2: %1?</translation>
    </message>
    <message>
        <source>Program command</source>
        <translation>Programmbefehl</translation>
    </message>
    <message>
        <source>Done: %1. PLC program %2.</source>
        <translation>Ausgeführt: %1. SPS-Programm %2.</translation>
    </message>
    <message>
        <source>Control (each asks first)</source>
        <translation>Steuerung (jede Aktion fragt vorher)</translation>
    </message>
</context>
<context>
    <name>cambench::Mc1Report</name>
    <message>
        <source>%1 variables read (V%2 to V%3); %4 of them are 0 and not listed.</source>
        <translation>%1 Variablen gelesen (V%2 bis V%3); %4 davon sind 0 und nicht aufgeführt.</translation>
    </message>
    <message>
        <source>The flags were not read.</source>
        <translation>Die Merker wurden nicht gelesen.</translation>
    </message>
    <message>
        <source>All %1 external flags are clear.</source>
        <translation>Alle %1 externen Merker sind gelöscht.</translation>
    </message>
    <message>
        <source>Of %1 external flags, these %2 are set: %3. All others are clear.</source>
        <translation>Von %1 externen Merkern sind diese %2 gesetzt: %3. Alle anderen sind gelöscht.</translation>
    </message>
    <message>
        <source>Parameter table in use: %1 - PROVISIONAL parameter numbers (a guess, not from the controller&apos;s documentation): the axis values above are not facts.</source>
        <translation>Verwendete Parametertabelle: %1 – VORLÄUFIGE Parameternummern (geraten, nicht aus der Dokumentation der Steuerung): die Achswerte oben sind keine Tatsachen.</translation>
    </message>
    <message>
        <source>Parameter table in use: %1.</source>
        <translation>Verwendete Parametertabelle: %1.</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Achse</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Read the controller for the report</source>
        <translation>Steuerung für den Bericht lesen</translation>
    </message>
    <message>
        <source>the %1 reports no program state</source>
        <translation>die %1 meldet keinen Programmzustand</translation>
    </message>
    <message>
        <source>axis %1: %2</source>
        <translation>Achse %1: %2</translation>
    </message>
    <message>
        <source>the %1 has no axis telegrams</source>
        <translation>die %1 hat keine Achstelegramme</translation>
    </message>
    <message>
        <source>Not read from the controller for this report.</source>
        <translation>Für diesen Bericht nicht aus der Steuerung gelesen.</translation>
    </message>
    <message>
        <source>Read from the controller at %1.</source>
        <translation>Aus der Steuerung gelesen am %1.</translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>Steuerung</translation>
    </message>
    <message>
        <source>Identity: %1</source>
        <translation>Identität: %1</translation>
    </message>
    <message>
        <source>PLC program</source>
        <translation>SPS-Programm</translation>
    </message>
    <message>
        <source>Not read: %1</source>
        <translation>Nicht gelesen: %1</translation>
    </message>
    <message>
        <source>Axes</source>
        <translation>Achsen</translation>
    </message>
    <message>
        <source>No axis read: %1</source>
        <translation>Keine Achse gelesen: %1</translation>
    </message>
    <message>
        <source>error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>moving</source>
        <translation>fährt</translation>
    </message>
    <message>
        <source>standing</source>
        <translation>steht</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>no</source>
        <translation>nein</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>Homed</source>
        <translation>Referenziert</translation>
    </message>
    <message>
        <source>Axes: %1.</source>
        <translation>Achsen: %1.</translation>
    </message>
    <message>
        <source>Variables</source>
        <translation>Variablen</translation>
    </message>
    <message>
        <source>External flags</source>
        <translation>Externe Merker</translation>
    </message>
</context>
<context>
    <name>cambench::Mc1SettingsWidget</name>
    <message>
        <source>Automatic (probe the controller)</source>
        <translation>Automatisch (Steuerung abfragen)</translation>
    </message>
    <message>
        <source>Automatic asks the controller and names what it found. A variant chosen here is checked against what answers.</source>
        <translation>Automatisch fragt die Steuerung und nennt, was gefunden wurde. Eine hier gewählte Variante wird mit dem geprüft, was antwortet.</translation>
    </message>
    <message>
        <source>RS232, 8N1. MC100: 9600 baud, RxD/TxD crossed. MC200: the baud rate set in the controller, a 1:1 cable; CamBench holds DTR high and RTS low, which power its interface.</source>
        <translation>RS232, 8N1. MC100: 9600 Baud, RxD/TxD gekreuzt. MC200: die in der Steuerung eingestellte Baudrate, ein 1:1-Kabel; CamBench hält DTR high und RTS low, die ihre Schnittstelle versorgen.</translation>
    </message>
    <message>
        <source>Controller:</source>
        <translation>Steuerung:</translation>
    </message>
    <message>
        <source>found by asking the controller</source>
        <translation>von der Steuerung erfragt</translation>
    </message>
    <message>
        <source>Empty: an MC200 is asked which axes it has (RDTABLE), and STOP goes to each of them. Axis numbers such as 1,2 name them instead.</source>
        <translation>Leer: eine MC200 wird gefragt, welche Achsen sie hat (RDTABLE), und STOPP geht an jede davon. Achsnummern wie 1,2 nennen sie stattdessen.</translation>
    </message>
    <message>
        <source>Axes:</source>
        <translation>Achsen:</translation>
    </message>
</context>
<context>
    <name>cambench::Mc1TrendPage</name>
    <message>
        <source>Trend</source>
        <translation>Trend</translation>
    </message>
    <message>
        <source>The first eight variables of the Variables page&apos;s watch list, read while this page or that one is shown.</source>
        <translation>Die ersten acht Variablen der Beobachtungsliste der Seite Variablen, gelesen, solange diese oder jene Seite angezeigt wird.</translation>
    </message>
</context>
<context>
    <name>cambench::Mc1VariablesPage</name>
    <message>
        <source>Variables</source>
        <translation>Variablen</translation>
    </message>
    <message>
        <source>Watch</source>
        <translation>Beobachten</translation>
    </message>
    <message>
        <source>Remove selected</source>
        <translation>Auswahl entfernen</translation>
    </message>
    <message>
        <source>Import names…</source>
        <translation>Namen importieren…</translation>
    </message>
    <message>
        <source>A CSV file of &quot;number;name&quot; lines, e.g. from the PLC program&apos;s variable list. The names stay on this PC.</source>
        <translation>Eine CSV-Datei mit Zeilen &quot;Nummer;Name&quot;, z. B. aus der Variablenliste des SPS-Programms. Die Namen bleiben auf diesem PC.</translation>
    </message>
    <message>
        <source>From</source>
        <translation>Von</translation>
    </message>
    <message>
        <source>to</source>
        <translation>bis</translation>
    </message>
    <message>
        <source>Import variable names</source>
        <translation>Variablennamen importieren</translation>
    </message>
    <message>
        <source>CSV files (*.csv *.txt);;All files (*)</source>
        <translation>CSV-Dateien (*.csv *.txt);;Alle Dateien (*)</translation>
    </message>
    <message numerus="yes">
        <source>%n variable(s) added to the watch list.</source>
        <translation>
            <numerusform>%n Variable zur Beobachtungsliste hinzugefügt.</numerusform>
            <numerusform>%n Variablen zur Beobachtungsliste hinzugefügt.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 could not be read: %2. Nothing was imported.</source>
        <translation>%1 konnte nicht gelesen werden: %2. Nichts wurde importiert.</translation>
    </message>
    <message>
        <source>%1 is not a name list (%2). Nothing was imported.</source>
        <translation>%1 ist keine Namensliste (%2). Nichts wurde importiert.</translation>
    </message>
    <message numerus="yes">
        <source>%n name(s) imported from %1.</source>
        <translation>
            <numerusform>%n Name aus %1 importiert.</numerusform>
            <numerusform>%n Namen aus %1 importiert.</numerusform>
        </translation>
    </message>
    <message>
        <source>Read variables</source>
        <translation>Variablen lesen</translation>
    </message>
    <message>
        <source>Not connected to an MC100/MC200: nothing was written.</source>
        <translation>Nicht mit einer MC100/MC200 verbunden: nichts wurde geschrieben.</translation>
    </message>
    <message>
        <source>Write</source>
        <translation>Schreiben</translation>
    </message>
    <message>
        <source>Write V%1 = %2 to the %3?</source>
        <translation>V%1 = %2 in die %3 schreiben?</translation>
    </message>
    <message>
        <source>The controller&apos;s PLC program uses this variable at once.</source>
        <translation>Das SPS-Programm der Steuerung verwendet diese Variable sofort.</translation>
    </message>
    <message>
        <source>Write variable</source>
        <translation>Variable schreiben</translation>
    </message>
    <message>
        <source>V%1 was not written: %2</source>
        <translation>V%1 wurde nicht geschrieben: %2</translation>
    </message>
    <message>
        <source>V%1 = %2 written and read back.</source>
        <translation>V%1 = %2 geschrieben und zurückgelesen.</translation>
    </message>
    <message>
        <source>V%1 reads back %2, not the %3 written.</source>
        <translation>V%1 liest %2 zurück, nicht die geschriebenen %3.</translation>
    </message>
    <message>
        <source>Open list…</source>
        <translation>Liste öffnen…</translation>
    </message>
    <message>
        <source>A watch list saved before (MC-1 project file): its variables, names and the values they had then, shown as not read until read.</source>
        <translation>Eine früher gespeicherte Beobachtungsliste (MC-1-Projektdatei): ihre Variablen, Namen und die damaligen Werte, als nicht gelesen angezeigt, bis sie gelesen sind.</translation>
    </message>
    <message>
        <source>Save list…</source>
        <translation>Liste speichern…</translation>
    </message>
    <message>
        <source>The watch list with its names and the values last read, as an MC-1 project file on this PC.</source>
        <translation>Die Beobachtungsliste mit ihren Namen und den zuletzt gelesenen Werten, als MC-1-Projektdatei auf diesem PC.</translation>
    </message>
    <message>
        <source>Open watch list</source>
        <translation>Beobachtungsliste öffnen</translation>
    </message>
    <message>
        <source>MC-1 projects (*.json)</source>
        <translation>MC-1-Projekte (*.json)</translation>
    </message>
    <message>
        <source>Save watch list</source>
        <translation>Beobachtungsliste speichern</translation>
    </message>
    <message>
        <source>Watch list saved to %1.</source>
        <translation>Beobachtungsliste in %1 gespeichert.</translation>
    </message>
    <message>
        <source>The watch list was not saved: %1</source>
        <translation>Die Beobachtungsliste wurde nicht gespeichert: %1</translation>
    </message>
    <message>
        <source>Nothing was opened: %1</source>
        <translation>Nichts wurde geöffnet: %1</translation>
    </message>
    <message numerus="yes">
        <source>%n variable(s) from %1; values shown as in the file until read.</source>
        <translation>
            <numerusform>%n Variable aus %1; Werte wie in der Datei, bis sie gelesen sind.</numerusform>
            <numerusform>%n Variablen aus %1; Werte wie in der Datei, bis sie gelesen sind.</numerusform>
        </translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a whole number: V%2 was not written.</source>
        <translation>„%1“ ist keine ganze Zahl: V%2 wurde nicht geschrieben.</translation>
    </message>
</context>
<context>
    <name>cambench::Mc1WatchModel</name>
    <message>
        <source>not read</source>
        <translation>nicht gelesen</translation>
    </message>
    <message>
        <source>stale, read %1</source>
        <translation>veraltet, gelesen %1</translation>
    </message>
    <message>
        <source>live</source>
        <translation>aktuell</translation>
    </message>
    <message>
        <source>Double-click to write a new value to the controller (it asks first).</source>
        <translation>Doppelklick schreibt einen neuen Wert in die Steuerung (fragt vorher).</translation>
    </message>
    <message>
        <source>Variable</source>
        <translation>Variable</translation>
    </message>
    <message>
        <source>Name (on this PC)</source>
        <translation>Name (auf diesem PC)</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <source>line %1: &quot;%2&quot; is not &quot;number;name&quot;</source>
        <translation>Zeile %1: &quot;%2&quot; ist nicht &quot;Nummer;Name&quot;</translation>
    </message>
    <message>
        <source>line %1: variable numbers end at 65535</source>
        <translation>Zeile %1: Variablennummern enden bei 65535</translation>
    </message>
    <message>
        <source>from the file, not read</source>
        <translation>aus der Datei, nicht gelesen</translation>
    </message>
    <message>
        <source>restored from last session, not read yet</source>
        <translation>aus der letzten Sitzung wiederhergestellt, noch nicht gelesen</translation>
    </message>
    <message>
        <source>on the controller: %1 (%2)</source>
        <translation>in der Steuerung: %1 (%2)</translation>
    </message>
</context>
<context>
    <name>cambench::Mc1Window</name>
    <message>
        <source>Identify controller</source>
        <translation>Steuerung erkennen</translation>
    </message>
    <message>
        <source>No MC100/MC200 identified itself: %1</source>
        <translation>Keine MC100/MC200 hat sich zu erkennen gegeben: %1</translation>
    </message>
    <message>
        <source>Back up controller (variables, flags)…</source>
        <translation>Steuerung sichern (Variablen, Merker)…</translation>
    </message>
    <message>
        <source>Back up controller</source>
        <translation>Steuerung sichern</translation>
    </message>
    <message>
        <source>MC-1 backups (*.json)</source>
        <translation>MC-1-Sicherungen (*.json)</translation>
    </message>
    <message>
        <source>Verify controller against backup…</source>
        <translation>Steuerung mit Sicherung vergleichen…</translation>
    </message>
    <message>
        <source>Verify against backup</source>
        <translation>Mit Sicherung vergleichen</translation>
    </message>
    <message>
        <source>Restore backup to controller…</source>
        <translation>Sicherung in Steuerung zurückspielen…</translation>
    </message>
    <message>
        <source>Restore backup</source>
        <translation>Sicherung zurückspielen</translation>
    </message>
    <message>
        <source>Backup</source>
        <translation>Sicherung</translation>
    </message>
    <message>
        <source>No backup was saved: %1</source>
        <translation>Keine Sicherung gespeichert: %1</translation>
    </message>
    <message>
        <source>Saved %1 variables and %2 flags to %3.</source>
        <translation>%1 Variablen und %2 Merker in %3 gesichert.</translation>
    </message>
    <message>
        <source>Verify</source>
        <translation>Vergleichen</translation>
    </message>
    <message>
        <source>Verify controller</source>
        <translation>Steuerung vergleichen</translation>
    </message>
    <message>
        <source>Not verified: %1</source>
        <translation>Nicht verglichen: %1</translation>
    </message>
    <message>
        <source>The controller holds all %1 values of %2.</source>
        <translation>Die Steuerung enthält alle %1 Werte aus %2.</translation>
    </message>
    <message numerus="yes">
        <source>%n difference(s) between the controller and %1:</source>
        <translation>
            <numerusform>%n Unterschied zwischen der Steuerung und %1:</numerusform>
            <numerusform>%n Unterschiede zwischen der Steuerung und %1:</numerusform>
        </translation>
    </message>
    <message>
        <source>Restore</source>
        <translation>Zurückspielen</translation>
    </message>
    <message>
        <source>Nothing was written: %1</source>
        <translation>Nichts wurde geschrieben: %1</translation>
    </message>
    <message>
        <source>Restore %1 (taken %2) to the controller?</source>
        <translation>%1 (gesichert %2) in die Steuerung zurückspielen?</translation>
    </message>
    <message>
        <source>It is checked against the controller first; then only the variables, flags and memory that differ are written. The PLC program uses them at once.</source>
        <translation>Die Datei wird zuerst mit der Steuerung geprüft; dann werden nur abweichende Variablen, Merker und Speicherbereiche geschrieben. Das SPS-Programm verwendet sie sofort.</translation>
    </message>
    <message>
        <source>Restore controller</source>
        <translation>Steuerung zurückspielen</translation>
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
    <message>
        <source>How often the device is asked for its state. CamBench polls no faster than the line can answer.</source>
        <translation>Wie oft das Gerät nach seinem Zustand gefragt wird. CamBench fragt nicht schneller ab, als die Leitung antworten kann.</translation>
    </message>
    <message>
        <source>The line needs about %1 ms per poll: polling every %2 ms instead of %3 ms.</source>
        <translation>Die Leitung braucht etwa %1 ms je Abfrage: Abfrage alle %2 ms statt %3 ms.</translation>
    </message>
    <message>
        <source>Waiting for the first answer.</source>
        <translation>Warten auf die erste Antwort.</translation>
    </message>
    <message>
        <source>Offline: no live values.</source>
        <translation>Offline: keine Live-Werte.</translation>
    </message>
    <message>
        <source>Live: last answer at %1.</source>
        <translation>Live: letzte Antwort um %1.</translation>
    </message>
    <message>
        <source>No answer since %1. The values below are from then, not live.</source>
        <translation>Keine Antwort seit %1. Die Werte unten sind von diesem Zeitpunkt, nicht live.</translation>
    </message>
    <message>
        <source>No answer from the device.</source>
        <translation>Keine Antwort vom Gerät.</translation>
    </message>
    <message>
        <source>Not polled: the values below are from %1.</source>
        <translation>Nicht abgefragt: die Werte unten sind von %1.</translation>
    </message>
    <message>
        <source>Not polled: no live values.</source>
        <translation>Nicht abgefragt: keine Live-Werte.</translation>
    </message>
    <message>
        <source>Value of %1</source>
        <translation>Wert von %1</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>unknown now; at %1: %2</source>
        <translation>jetzt unbekannt; um %1: %2</translation>
    </message>
</context>
<context>
    <name>cambench::MotionLeaveQuestion</name>
    <message>
        <source>On the device something moves or is powered:</source>
        <translation>Auf dem Gerät bewegt sich etwas oder ist bestromt:</translation>
    </message>
    <message>
        <source>CamBench could not tell whether something on the device moves or is powered.</source>
        <translation>CamBench konnte nicht feststellen, ob sich auf dem Gerät etwas bewegt oder bestromt ist.</translation>
    </message>
    <message>
        <source>STOP, then %1</source>
        <translation>STOPP, dann %1</translation>
    </message>
    <message>
        <source>%1 without stopping</source>
        <translation>%1 ohne Stoppen</translation>
    </message>
    <message>
        <source>The STOP was not acknowledged everywhere, so CamBench stays connected and STOP can be pressed again. Use the machine&apos;s emergency stop.

%1</source>
        <translation>Der STOPP wurde nicht überall quittiert; CamBench bleibt deshalb verbunden, und STOPP kann erneut gedrückt werden. Betätigen Sie den Not-Halt der Maschine.

%1</translation>
    </message>
</context>
<context>
    <name>cambench::MotionStop</name>
    <message>
        <source>STOP</source>
        <translation>STOPP</translation>
    </message>
    <message>
        <source>Ask what moves</source>
        <translation>Fragen, was sich bewegt</translation>
    </message>
    <message>
        <source>The device</source>
        <translation>Das Gerät</translation>
    </message>
    <message>
        <source>not connected: the STOP was not sent</source>
        <translation>nicht verbunden: der STOPP wurde nicht gesendet</translation>
    </message>
    <message>
        <source>it has nothing CamBench can stop</source>
        <translation>es hat nichts, was CamBench stoppen kann</translation>
    </message>
    <message>
        <source>the device is not connected</source>
        <translation>das Gerät ist nicht verbunden</translation>
    </message>
    <message>
        <source>the device has nothing CamBench can stop</source>
        <translation>das Gerät hat nichts, was CamBench stoppen kann</translation>
    </message>
    <message>
        <source>no answer within %1 s</source>
        <translation>keine Antwort innerhalb von %1 s</translation>
    </message>
    <message>
        <source>no report of the STOP within %1 s</source>
        <translation>keine Meldung des STOPPs innerhalb von %1 s</translation>
    </message>
    <message>
        <source>STOP acknowledged by every axis and drive.</source>
        <translation>STOPP von jeder Achse und jedem Antrieb quittiert.</translation>
    </message>
    <message>
        <source>STOP NOT acknowledged everywhere – use the machine&apos;s emergency stop.</source>
        <translation>STOPP NICHT überall quittiert – benutzen Sie den Not-Halt der Maschine.</translation>
    </message>
    <message>
        <source>%1: acknowledged</source>
        <translation>%1: quittiert</translation>
    </message>
    <message>
        <source>%1: NOT acknowledged – use the machine&apos;s emergency stop</source>
        <translation>%1: NICHT quittiert – benutzen Sie den Not-Halt der Maschine</translation>
    </message>
    <message>
        <source>Nothing answered the STOP – use the machine&apos;s emergency stop</source>
        <translation>Nichts hat auf den STOPP geantwortet – benutzen Sie den Not-Halt der Maschine</translation>
    </message>
    <message>
        <source>STOP acknowledged at %1</source>
        <translation>STOPP quittiert um %1</translation>
    </message>
    <message>
        <source>may move: STOP NOT acknowledged at %1</source>
        <translation>kann fahren: STOPP NICHT quittiert um %1</translation>
    </message>
    <message>
        <source>moving (%1)</source>
        <translation>fährt (%1)</translation>
    </message>
    <message>
        <source>standing (%1)</source>
        <translation>steht (%1)</translation>
    </message>
    <message>
        <source>may move (%1)</source>
        <translation>kann fahren (%1)</translation>
    </message>
    <message>
        <source>may move: moving when last read at %1</source>
        <translation>kann fahren: fuhr beim letzten Lesen um %1</translation>
    </message>
    <message>
        <source>may move: %1 sent at %2</source>
        <translation>kann fahren: %1 gesendet um %2</translation>
    </message>
    <message>
        <source>Nothing to stop: nothing was powered, and nothing was sent.</source>
        <translation>Nichts zu stoppen: nichts war bestromt, und nichts wurde gesendet.</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1: not powered, nothing to stop</source>
        <translation>%1: nicht bestromt, nichts zu stoppen</translation>
    </message>
</context>
<context>
    <name>cambench::MultiTrendChart</name>
    <message>
        <source>seconds</source>
        <translation>Sekunden</translation>
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
    <name>cambench::PlcCouplingPage</name>
    <message>
        <source>PLC coupling</source>
        <translation>SPS-Kopplung</translation>
    </message>
    <message>
        <source>none on</source>
        <translation>keiner ein</translation>
    </message>
    <message>
        <source>on: %1</source>
        <translation>ein: %1</translation>
    </message>
    <message>
        <source>An S7 with a CP340 drives the CamCon with the short commands 0x01 to 0x07. This page sends the same telegrams as the function block and shows the answers as the data block holds them. When the CamCon answers here as expected, look for the fault in the PLC program or the CP340&apos;s settings.</source>
        <translation>Eine S7 mit CP340 steuert das CamCon mit den Kurzbefehlen 0x01 bis 0x07. Diese Seite sendet dieselben Telegramme wie der Funktionsbaustein und zeigt die Antworten so, wie der Datenbaustein sie enthält. Antwortet das CamCon hier wie erwartet, liegt der Fehler im SPS-Programm oder in den Einstellungen des CP340.</translation>
    </message>
    <message>
        <source>Read status (0x01)</source>
        <translation>Status lesen (0x01)</translation>
    </message>
    <message>
        <source>Reset errors (0x02)</source>
        <translation>Fehler quittieren (0x02)</translation>
    </message>
    <message>
        <source>Change program (0x03)</source>
        <translation>Programm wechseln (0x03)</translation>
    </message>
    <message>
        <source>Program:</source>
        <translation>Programm:</translation>
    </message>
    <message>
        <source>Area 1: status</source>
        <translation>Bereich 1: Status</translation>
    </message>
    <message>
        <source>On</source>
        <translation>Ein</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <source>Read cams (0x04)</source>
        <translation>Nocken lesen (0x04)</translation>
    </message>
    <message>
        <source>Write cams (0x05)…</source>
        <translation>Nocken schreiben (0x05)…</translation>
    </message>
    <message>
        <source>Add cam</source>
        <translation>Nocke hinzufügen</translation>
    </message>
    <message>
        <source>Remove cam</source>
        <translation>Nocke entfernen</translation>
    </message>
    <message>
        <source>Output:</source>
        <translation>Ausgang:</translation>
    </message>
    <message>
        <source>Area 2: cam table</source>
        <translation>Bereich 2: Nockentabelle</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>Read dead time (0x06)</source>
        <translation>Totzeit lesen (0x06)</translation>
    </message>
    <message>
        <source>Write dead time (0x07)…</source>
        <translation>Totzeit schreiben (0x07)…</translation>
    </message>
    <message>
        <source>Area 3: dead times (of the output above)</source>
        <translation>Bereich 3: Totzeiten (des Ausgangs oben)</translation>
    </message>
    <message>
        <source>Not read yet.</source>
        <translation>Noch nicht gelesen.</translation>
    </message>
    <message>
        <source>%1 failed: %2</source>
        <translation>%1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>outputs %1–%2: %3</source>
        <translation>Ausgänge %1–%2: %3</translation>
    </message>
    <message>
        <source>A PLC program reading the status sees: actual value %1, speed %2, program %3 active, device status %4, %5 outputs, %6. To change the program it writes the wanted number into DW 34; the function block sends 0x03 while DW 14 and DW 34 differ.</source>
        <translation>Ein SPS-Programm, das den Status liest, sieht: Istwert %1, Geschwindigkeit %2, Programm %3 aktiv, Gerätestatus %4, %5 Ausgänge, %6. Zum Programmwechsel schreibt es die gewünschte Nummer in DW 34; der Funktionsbaustein sendet 0x03, solange DW 14 und DW 34 verschieden sind.</translation>
    </message>
    <message>
        <source>none of them on</source>
        <translation>keiner davon ein</translation>
    </message>
    <message>
        <source>Read the status (0x01)</source>
        <translation>Status lesen (0x01)</translation>
    </message>
    <message>
        <source>Not read: the status is unknown.</source>
        <translation>Nicht gelesen: der Status ist unbekannt.</translation>
    </message>
    <message>
        <source>Reading the status</source>
        <translation>Lesen des Status</translation>
    </message>
    <message>
        <source>Reset the errors (0x02)</source>
        <translation>Fehler quittieren (0x02)</translation>
    </message>
    <message>
        <source>Switch the CamCon to program %1 (0x03)? Its outputs follow the cams of program %1 at once.</source>
        <translation>Das CamCon auf Programm %1 umschalten (0x03)? Seine Ausgänge folgen sofort den Nocken von Programm %1.</translation>
    </message>
    <message>
        <source>Change the program (0x03)</source>
        <translation>Programm wechseln (0x03)</translation>
    </message>
    <message>
        <source>Read the cams (0x04)</source>
        <translation>Nocken lesen (0x04)</translation>
    </message>
    <message>
        <source>Reading the cams</source>
        <translation>Lesen der Nocken</translation>
    </message>
    <message>
        <source>Program %1, output %2: %3 cams as a PLC reads them (DB+0 AUSG_NR %2, DB+1 ANZ_NOCKEN %3).</source>
        <translation>Programm %1, Ausgang %2: %3 Nocken, wie eine SPS sie liest (DB+0 AUSG_NR %2, DB+1 ANZ_NOCKEN %3).</translation>
    </message>
    <message>
        <source>Replace the cams of output %1 in program %2 by the %3 cams shown (0x05)? If program %2 runs, output %1 switches by them at once.</source>
        <translation>Die Nocken von Ausgang %1 in Programm %2 durch die %3 gezeigten Nocken ersetzen (0x05)? Läuft Programm %2, schaltet Ausgang %1 sofort danach.</translation>
    </message>
    <message>
        <source>Write the cams (0x05)</source>
        <translation>Nocken schreiben (0x05)</translation>
    </message>
    <message>
        <source>Read the dead time (0x06)</source>
        <translation>Totzeit lesen (0x06)</translation>
    </message>
    <message>
        <source>Not read: the dead time is unknown.</source>
        <translation>Nicht gelesen: die Totzeit ist unbekannt.</translation>
    </message>
    <message>
        <source>Reading the dead time</source>
        <translation>Lesen der Totzeit</translation>
    </message>
    <message>
        <source>Set the dead time of output %1 to %2 (0x07)? The output switches that much earlier from now on.</source>
        <translation>Die Totzeit von Ausgang %1 auf %2 setzen (0x07)? Der Ausgang schaltet ab sofort um so viel früher.</translation>
    </message>
    <message>
        <source>Write the dead time (0x07)</source>
        <translation>Totzeit schreiben (0x07)</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>nicht gelesen</translation>
    </message>
    <message>
        <source>Read at %1.</source>
        <translation>Gelesen um %1.</translation>
    </message>
    <message>
        <source>read at %1</source>
        <translation>gelesen um %1</translation>
    </message>
    <message>
        <source>Enter the dead time to write first (or read it from the device).</source>
        <translation>Geben Sie zuerst die zu schreibende Totzeit ein (oder lesen Sie sie aus dem Gerät).</translation>
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
        <source>PLC</source>
        <translation>SPS</translation>
    </message>
    <message>
        <source>Reading %1…</source>
        <translation>%1 wird gelesen…</translation>
    </message>
</context>
<context>
    <name>cambench::ProgrammingProgramPage</name>
    <message>
        <source>Programming program</source>
        <translation>Programmierprogramm</translation>
    </message>
    <message>
        <source>Slow</source>
        <translation>Langsam</translation>
    </message>
    <message>
        <source>Direct (within one cycle)</source>
        <translation>Direkt (innerhalb eines Zyklus)</translation>
    </message>
    <message>
        <source>At the actual value</source>
        <translation>Am Istwert</translation>
    </message>
    <message>
        <source>The table interface reads and writes the cams of this program. It need not be the program that runs the machine.</source>
        <translation>Die Tabellenschnittstelle liest und schreibt die Nocken dieses Programms. Es muss nicht das Programm sein, mit dem die Maschine läuft.</translation>
    </message>
    <message>
        <source>Program:</source>
        <translation>Programm:</translation>
    </message>
    <message>
        <source>Program selection:</source>
        <translation>Programmanwahl:</translation>
    </message>
    <message>
        <source>Selection actual value:</source>
        <translation>Istwert für die Anwahl:</translation>
    </message>
    <message>
        <source>Read the programming program</source>
        <translation>Programmierprogramm lesen</translation>
    </message>
    <message>
        <source>Reading the programming program failed: %1</source>
        <translation>Lesen des Programmierprogramms fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>On the device: %1</source>
        <translation>Im Gerät: %1</translation>
    </message>
    <message>
        <source>Not read from the device yet: the values shown are not the device&apos;s.</source>
        <translation>Noch nicht aus dem Gerät gelesen: die gezeigten Werte sind nicht die des Geräts.</translation>
    </message>
    <message>
        <source>Edited, not written to the device.</source>
        <translation>Geändert, nicht ins Gerät geschrieben.</translation>
    </message>
    <message>
        <source>As on the device.</source>
        <translation>Wie im Gerät.</translation>
    </message>
    <message>
        <source>From the project, not read from the device: write it or read the device.</source>
        <translation>Aus dem Projekt, nicht vom Gerät gelesen: schreiben Sie es oder lesen Sie das Gerät.</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>nicht gelesen</translation>
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
    <message>
        <source>%1 s so far. No time left is given: how much the device holds is not known before it is read.</source>
        <translation>Bisher %1 s. Keine Restzeit: wie viel das Gerät enthält, ist vor dem Lesen nicht bekannt.</translation>
    </message>
</context>
<context>
    <name>cambench::RangeDelegate</name>
    <message>
        <source>%1%2 is not taken: this device allows %3 … %4%2.</source>
        <translation>%1%2 wird nicht übernommen: dieses Gerät erlaubt %3 … %4%2.</translation>
    </message>
    <message>
        <source>The cell keeps its value.</source>
        <translation>Die Zelle behält ihren Wert.</translation>
    </message>
</context>
<context>
    <name>cambench::ReplaceEditsDialog</name>
    <message>
        <source>Cam programs</source>
        <translation>Nockenprogramme</translation>
    </message>
    <message>
        <source>Output names and dead times</source>
        <translation>Ausgangsnamen und Totzeiten</translation>
    </message>
    <message>
        <source>Encoder and system settings</source>
        <translation>Geber- und Systemeinstellungen</translation>
    </message>
    <message>
        <source>Users</source>
        <translation>Benutzer</translation>
    </message>
    <message>
        <source>PLC networks</source>
        <translation>SPS-Netzwerke</translation>
    </message>
    <message>
        <source>Values read from the device</source>
        <translation>Aus dem Gerät gelesene Werte</translation>
    </message>
    <message>
        <source>Values from the project file</source>
        <translation>Werte aus der Projektdatei</translation>
    </message>
    <message>
        <source>The device&apos;s values would replace edits that are not written yet. For each section: keep your edits, or take the device&apos;s values?</source>
        <translation>Die Werte des Geräts würden noch nicht geschriebene Änderungen ersetzen. Für jeden Bereich: Ihre Änderungen behalten oder die Werte des Geräts übernehmen?</translation>
    </message>
    <message>
        <source>The project&apos;s values would replace edits that are not written yet. For each section: keep your edits, or take the project&apos;s values?</source>
        <translation>Die Werte des Projekts würden noch nicht geschriebene Änderungen ersetzen. Für jeden Bereich: Ihre Änderungen behalten oder die Werte des Projekts übernehmen?</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n edit(s)</source>
        <translation>
            <numerusform>%1: %n Änderung</numerusform>
            <numerusform>%1: %n Änderungen</numerusform>
        </translation>
    </message>
    <message>
        <source>Keep my edits</source>
        <translation>Meine Änderungen behalten</translation>
    </message>
    <message>
        <source>Take the device&apos;s values</source>
        <translation>Werte des Geräts übernehmen</translation>
    </message>
    <message>
        <source>Take the project&apos;s values</source>
        <translation>Werte des Projekts übernehmen</translation>
    </message>
    <message>
        <source>Items you did not edit take the device&apos;s values either way. Taking the device&apos;s cam programs can be undone (Edit → Undo).</source>
        <translation>Elemente, die Sie nicht bearbeitet haben, übernehmen in jedem Fall die Werte des Geräts. Das Übernehmen der Nockenprogramme des Geräts lässt sich rückgängig machen (Bearbeiten → Rückgängig).</translation>
    </message>
    <message>
        <source>Items you did not edit take the project&apos;s values either way.</source>
        <translation>Elemente, die Sie nicht bearbeitet haben, übernehmen in jedem Fall die Werte des Projekts.</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Anwenden</translation>
    </message>
    <message>
        <source>Cancel: change nothing</source>
        <translation>Abbrechen: nichts ändern</translation>
    </message>
    <message numerus="yes">
        <source>… and %n more</source>
        <translation>
            <numerusform>… und %n weiterer</numerusform>
            <numerusform>… und %n weitere</numerusform>
        </translation>
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
        <translation>
            <numerusform>bis zu %n Zeichen</numerusform>
            <numerusform>bis zu %n Zeichen</numerusform>
        </translation>
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
    <message>
        <source>Not allowed: %1.</source>
        <translation>Nicht erlaubt: %1.</translation>
    </message>
    <message>
        <source>The device holds a value outside the allowed range: %1. It is shown as the device has it, not changed.</source>
        <translation>Das Gerät enthält einen Wert außerhalb des erlaubten Bereichs: %1. Er wird gezeigt, wie das Gerät ihn hat, nicht verändert.</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
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
        <source>Reading settings…</source>
        <translation>Einstellungen werden gelesen…</translation>
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
        <source>Encoder &amp; system</source>
        <translation>Geber &amp; System</translation>
    </message>
</context>
<context>
    <name>cambench::Shell</name>
    <message>
        <source>Open machine</source>
        <translation>Maschine öffnen</translation>
    </message>
    <message>
        <source>Machine file (*.json)</source>
        <translation>Maschinendatei (*.json)</translation>
    </message>
    <message>
        <source>Open demo machine</source>
        <translation>Demo-Maschine öffnen</translation>
    </message>
    <message>
        <source>New machine</source>
        <translation>Neue Maschine</translation>
    </message>
    <message>
        <source>Name of the machine:</source>
        <translation>Name der Maschine:</translation>
    </message>
    <message>
        <source>Add the machine&apos;s devices: Machine → Add device…</source>
        <translation>Fügen Sie die Geräte der Maschine hinzu: Maschine → Gerät hinzufügen…</translation>
    </message>
</context>
<context>
    <name>cambench::StopBar</name>
    <message>
        <source>STOP (%1)</source>
        <translation>STOPP (%1)</translation>
    </message>
    <message>
        <source>STOP sent…</source>
        <translation>STOPP gesendet…</translation>
    </message>
    <message>
        <source>%1 %2
%3</source>
        <translation>%1 %2
%3</translation>
    </message>
    <message>
        <source>Stops every axis and drive of the device, without a question, ahead of everything waiting for the line. %1 stops it too, from every window, dialog and menu of CamBench.</source>
        <translation>Stoppt jede Achse und jeden Antrieb des Geräts ohne Rückfrage, vor allem, was auf die Leitung wartet. %1 stoppt es ebenfalls, aus jedem Fenster, Dialog und Menü von CamBench.</translation>
    </message>
</context>
<context>
    <name>cambench::TableSettingsWidget</name>
    <message>
        <source>3964R n96 (9600 baud, 8N1)</source>
        <translation>3964R n96 (9600 Baud, 8N1)</translation>
    </message>
    <message>
        <source>3964R e38 (38400 baud, 8E1)</source>
        <translation>3964R e38 (38400 Baud, 8E1)</translation>
    </message>
    <message>
        <source>The serial mode the device&apos;s menu &quot;Ser:&quot; shows.</source>
        <translation>Die serielle Betriebsart, die das Menü „Ser:“ des Geräts zeigt.</translation>
    </message>
    <message>
        <source>Point to point: no device number. 3964R e38 reaches only the data words 0–127 of each area: 62 cams per track and no dead-time modes; n96 reaches all.</source>
        <translation>Punkt zu Punkt: keine Gerätenummer. 3964R e38 erreicht nur die Datenwörter 0–127 jedes Bereichs: 62 Nocken je Spur und keine Totzeit-Modi; n96 erreicht alle.</translation>
    </message>
    <message>
        <source>Variant:</source>
        <translation>Variante:</translation>
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
    <name>cambench::TimingBar</name>
    <message>
        <source>Program %1 has no cams.</source>
        <translation>Programm %1 hat keine Nocken.</translation>
    </message>
    <message numerus="yes">
        <source>At %1: %n warning(s). %2</source>
        <translation>
            <numerusform>Bei %1: %n Warnung. %2</numerusform>
            <numerusform>Bei %1: %n Warnungen. %2</numerusform>
        </translation>
    </message>
    <message>
        <source>At %1 every cam switches as drawn. First limit: %2</source>
        <translation>Bei %1 schaltet jede Nocke wie gezeichnet. Erste Grenze: %2</translation>
    </message>
    <message>
        <source>At %1 every cam switches as drawn, at any speed.</source>
        <translation>Bei %1 schaltet jede Nocke wie gezeichnet, bei jeder Geschwindigkeit.</translation>
    </message>
    <message>
        <source>The device&apos;s speed is no longer live; shown at the last speed read.</source>
        <translation>Die Geschwindigkeit des Geräts ist nicht mehr live; gezeigt bei der zuletzt gelesenen.</translation>
    </message>
    <message>
        <source>Timing at speed</source>
        <translation>Schaltzeiten bei Geschwindigkeit</translation>
    </message>
    <message>
        <source>Draws under every output where it really switches at this speed: the device switches each edge early by speed × dead time so that the actuator acts at the programmed position. Durations in ms; warnings where cams vanish, merge or are shorter than the output&apos;s minimum pulse (track table).</source>
        <translation>Zeichnet unter jeden Ausgang, wo er bei dieser Geschwindigkeit wirklich schaltet: Das Gerät schaltet jede Flanke um Geschwindigkeit × Totzeit früher, damit der Aktor an der programmierten Position wirkt. Dauern in ms; Warnungen, wo Nocken verschwinden, verschmelzen oder kürzer sind als der Mindestimpuls des Ausgangs (Spurtabelle).</translation>
    </message>
    <message>
        <source>Device speed</source>
        <translation>Gerätegeschwindigkeit</translation>
    </message>
    <message>
        <source>Follow the speed the device measures, live.</source>
        <translation>Der vom Gerät gemessenen Geschwindigkeit live folgen.</translation>
    </message>
    <message>
        <source>The device&apos;s speed is shown while the monitor reads it live (connected, Monitor or diagram polling).</source>
        <translation>Die Geschwindigkeit des Geräts gibt es, solange der Monitor sie live liest (verbunden, Monitor oder Diagramm fragt ab).</translation>
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
        <source>Output %1 is the same as on the device.</source>
        <translation>Ausgang %1 ist wie im Gerät.</translation>
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
    <message>
        <source>not read</source>
        <translation>nicht gelesen</translation>
    </message>
    <message>
        <source>Program %1 was not read from the device: what the device holds is unknown. The cams shown exist on this PC.</source>
        <translation>Programm %1 wurde nicht aus dem Gerät gelesen: was das Gerät enthält, ist unbekannt. Die gezeigten Nocken gibt es auf diesem PC.</translation>
    </message>
    <message>
        <source>The shortest time output %1 must stay on for its actuator to act. The timing view warns where a cam is on for less at the speed chosen. Kept on this PC and in the project file, not on the device.</source>
        <translation>Die kürzeste Zeit, die Ausgang %1 eingeschaltet bleiben muss, damit sein Aktor wirkt. Die Schaltzeit-Ansicht warnt, wo eine Nocke bei der gewählten Geschwindigkeit kürzer eingeschaltet ist. Nur auf diesem PC und in der Projektdatei, nicht im Gerät.</translation>
    </message>
    <message>
        <source>Min. pulse</source>
        <translation>Min.-Impuls</translation>
    </message>
    <message>
        <source>The cams of output %1 were changed and are not yet written to the device.</source>
        <translation>Die Nocken von Ausgang %1 wurden geändert und sind noch nicht ins Gerät geschrieben.</translation>
    </message>
    <message>
        <source>The name of output %1 was changed and is not yet written to the device.</source>
        <translation>Der Name von Ausgang %1 wurde geändert und ist noch nicht ins Gerät geschrieben.</translation>
    </message>
    <message>
        <source>The dead time of output %1 was changed and is not yet written to the device.</source>
        <translation>Die Totzeit von Ausgang %1 wurde geändert und ist noch nicht ins Gerät geschrieben.</translation>
    </message>
    <message>
        <source>The cams of output %1 are the same as on the device. Its name and dead time were not read from it.</source>
        <translation>Die Nocken von Ausgang %1 sind dieselben wie im Gerät. Sein Name und seine Totzeit wurden nicht aus dem Gerät gelesen.</translation>
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
        <source>New user</source>
        <translation>Neuer Benutzer</translation>
    </message>
    <message>
        <source>hidden – check &quot;Show numbers&quot; to see or change it</source>
        <translation>verborgen – „Nummern zeigen“ anhaken, um sie zu sehen oder zu ändern</translation>
    </message>
    <message>
        <source>Reading users…</source>
        <translation>Benutzer werden gelesen…</translation>
    </message>
    <message>
        <source>Reading users failed: %1</source>
        <translation>Lesen der Benutzer fehlgeschlagen: %1</translation>
    </message>
    <message numerus="yes">
        <source>%n user(s) read.</source>
        <translation>
            <numerusform>%n Benutzer gelesen.</numerusform>
            <numerusform>%n Benutzer gelesen.</numerusform>
        </translation>
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
        <source>User &quot;%1&quot;</source>
        <translation>Benutzer „%1“</translation>
    </message>
    <message>
        <source>deleted</source>
        <translation>gelöscht</translation>
    </message>
    <message>
        <source>Users</source>
        <translation>Benutzer</translation>
    </message>
</context>
<context>
    <name>cambench::comm</name>
    <message>
        <source>baud rate %1 is not a positive number</source>
        <translation>Baudrate %1 ist keine positive Zahl</translation>
    </message>
    <message>
        <source>%1 data bits: use 5, 6, 7 or 8</source>
        <translation>%1 Datenbits: verwenden Sie 5, 6, 7 oder 8</translation>
    </message>
    <message>
        <source>parity &apos;%1&apos;: use N, E, O, S or M</source>
        <translation>Parität &apos;%1&apos;: verwenden Sie N, E, O, S oder M</translation>
    </message>
    <message>
        <source>%1 stop bits: use 1, 2 or 3 (one and a half)</source>
        <translation>%1 Stoppbits: verwenden Sie 1, 2 oder 3 (eineinhalb)</translation>
    </message>
    <message>
        <source>flow control &apos;%1&apos;: use N (none), H (RTS/CTS) or S (XON/XOFF)</source>
        <translation>Flusssteuerung &apos;%1&apos;: verwenden Sie N (keine), H (RTS/CTS) oder S (XON/XOFF)</translation>
    </message>
    <message>
        <source>cannot use %1: %2</source>
        <translation>%1 nicht verwendbar: %2</translation>
    </message>
    <message>
        <source>check the port name and that no other program uses it</source>
        <translation>prüfen Sie den Namen der Schnittstelle und dass kein anderes Programm sie benutzt</translation>
    </message>
    <message>
        <source>check the port name and that the adapter is plugged in</source>
        <translation>prüfen Sie den Namen der Schnittstelle und dass der Adapter eingesteckt ist</translation>
    </message>
    <message>
        <source>cannot open %1: %2; %3</source>
        <translation>%1 kann nicht geöffnet werden: %2; %3</translation>
    </message>
    <message>
        <source>the port %1 disappeared (cable pulled or adapter removed); reconnect and retry</source>
        <translation>die Schnittstelle %1 ist verschwunden (Kabel gezogen oder Adapter entfernt); verbinden Sie neu und versuchen Sie es erneut</translation>
    </message>
    <message>
        <source>%1 %2 failed: %3; reconnect and retry</source>
        <translation>%1 %2 fehlgeschlagen: %3; verbinden Sie neu und versuchen Sie es erneut</translation>
    </message>
    <message>
        <source>the port %1 is not open; connect first</source>
        <translation>die Schnittstelle %1 ist nicht geöffnet; verbinden Sie zuerst</translation>
    </message>
    <message>
        <source>could not send %1 bytes to %2 within %3 ms; check the flow control setting (RTS/CTS needs the CTS line)</source>
        <translation>%1 Bytes konnten nicht innerhalb von %3 ms an %2 gesendet werden; prüfen Sie die Flusssteuerung (RTS/CTS braucht die CTS-Leitung)</translation>
    </message>
    <message>
        <source>reading from</source>
        <translation>Lesen von</translation>
    </message>
    <message>
        <source>no answer within %1 ms</source>
        <translation>keine Antwort innerhalb von %1 ms</translation>
    </message>
    <message>
        <source>cannot connect to %1: %2; check the address, the port and that the device server is switched on</source>
        <translation>Verbindung zu %1 nicht möglich: %2; prüfen Sie Adresse, Port und dass der Geräteserver eingeschaltet ist</translation>
    </message>
    <message>
        <source>the device server %1 closed the connection; reconnect and retry</source>
        <translation>der Geräteserver %1 hat die Verbindung geschlossen; verbinden Sie neu und versuchen Sie es erneut</translation>
    </message>
    <message>
        <source>the connection to %1 failed: %2; reconnect and retry</source>
        <translation>die Verbindung zu %1 ist fehlgeschlagen: %2; verbinden Sie neu und versuchen Sie es erneut</translation>
    </message>
    <message>
        <source>not connected to %1; connect first</source>
        <translation>nicht mit %1 verbunden; verbinden Sie zuerst</translation>
    </message>
    <message>
        <source>could not send %1 bytes to %2 within %3 ms; check the network</source>
        <translation>%1 Bytes konnten nicht innerhalb von %3 ms an %2 gesendet werden; prüfen Sie das Netzwerk</translation>
    </message>
    <message>
        <source>write it as tcp://host:port, e.g. tcp://10.0.0.5:4001</source>
        <translation>schreiben Sie tcp://host:port, z. B. tcp://10.0.0.5:4001</translation>
    </message>
    <message>
        <source>&apos;%1&apos; names no host; %2</source>
        <translation>&apos;%1&apos; nennt keinen Host; %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; names no TCP port (1..65535); %2</source>
        <translation>&apos;%1&apos; nennt keinen TCP-Port (1..65535); %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has more than a host and a port; %2</source>
        <translation>&apos;%1&apos; enthält mehr als Host und Port; %2</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: unknown scheme; use tcp://host:port, a serial port name or sim</source>
        <translation>&apos;%1&apos;: unbekanntes Schema; verwenden Sie tcp://host:port, den Namen einer seriellen Schnittstelle oder sim</translation>
    </message>
    <message>
        <source>no port given; name a serial port (/dev/ttyUSB0, COM3), tcp://host:port or sim</source>
        <translation>keine Schnittstelle angegeben; nennen Sie eine serielle Schnittstelle (/dev/ttyUSB0, COM3), tcp://host:port oder sim</translation>
    </message>
    <message>
        <source>&apos;%1&apos; names no port this program can open</source>
        <translation>&apos;%1&apos; nennt keine Schnittstelle, die dieses Programm öffnen kann</translation>
    </message>
    <message>
        <source>the request could not be sent</source>
        <translation>die Anfrage konnte nicht gesendet werden</translation>
    </message>
    <message>
        <source>no reply, though the device answered %1</source>
        <translation>keine Antwort, obwohl das Gerät %1 geantwortet hat</translation>
    </message>
    <message>
        <source>no valid reply (last: %1)</source>
        <translation>keine gültige Antwort (zuletzt: %1)</translation>
    </message>
    <message>
        <source>not connected to a device; connect first</source>
        <translation>mit keinem Gerät verbunden; verbinden Sie zuerst</translation>
    </message>
    <message>
        <source>the connection %1 closed; reconnect and retry</source>
        <translation>die Verbindung %1 wurde geschlossen; verbinden Sie neu und versuchen Sie es erneut</translation>
    </message>
    <message>
        <source>not connected: connecting to %1</source>
        <translation>nicht verbunden: Verbindung zu %1 wird aufgebaut</translation>
    </message>
    <message>
        <source>unknown protocol &quot;%1&quot;; known: %2</source>
        <translation>unbekanntes Protokoll „%1“; bekannt: %2</translation>
    </message>
    <message>
        <source>not connected: %1</source>
        <translation>nicht verbunden: %1</translation>
    </message>
    <message>
        <source>Users and rights exist only in %1.</source>
        <translation>Benutzer und Rechte gibt es nur in %1.</translation>
    </message>
    <message>
        <source>EEPROM backup and restore exist only in %1.</source>
        <translation>Sichern und Wiederherstellen des EEPROMs gibt es nur in %1.</translation>
    </message>
    <message>
        <source>Typed requests exist only in %1.</source>
        <translation>Eingetippte Anfragen gibt es nur in %1.</translation>
    </message>
    <message>
        <source>Output and program names exist only in %1.</source>
        <translation>Ausgangs- und Programmnamen gibt es nur in %1.</translation>
    </message>
    <message>
        <source>This protocol does not reach the PLC logic module.</source>
        <translation>Dieses Protokoll erreicht das SPS-Logikmodul nicht.</translation>
    </message>
    <message>
        <source>Dead-time modes exist only in %1.</source>
        <translation>Totzeit-Modi gibt es nur in %1.</translation>
    </message>
    <message>
        <source>Analogue cams exist only in %1.</source>
        <translation>Analognocken gibt es nur in %1.</translation>
    </message>
    <message>
        <source>The EEPROM lock exists only in %1.</source>
        <translation>Die EEPROM-Sperre gibt es nur in %1.</translation>
    </message>
    <message>
        <source>bytes outside any frame</source>
        <translation>Bytes außerhalb eines Rahmens</translation>
    </message>
    <message>
        <source>a frame ended by CR without LF</source>
        <translation>ein Rahmen, der mit CR ohne LF endet</translation>
    </message>
    <message>
        <source>No frame end within %1 bytes; the frame was dropped.</source>
        <translation>Kein Rahmenende innerhalb von %1 Bytes; der Rahmen wurde verworfen.</translation>
    </message>
    <message>
        <source>the rest of an oversized frame</source>
        <translation>der Rest eines übergroßen Rahmens</translation>
    </message>
    <message>
        <source>The frame has no checksum characters.</source>
        <translation>Der Rahmen hat keine Prüfsummenzeichen.</translation>
    </message>
    <message>
        <source>Checksum %1 received, %2 expected.</source>
        <translation>Prüfsumme %1 empfangen, %2 erwartet.</translation>
    </message>
    <message>
        <source>Skipped %1 bytes: %2.</source>
        <translation>%1 Bytes übersprungen: %2.</translation>
    </message>
    <message>
        <source>The value %1 of field &quot;%2&quot; is outside %3..%4 (%5 hex digits); use a value in that range.</source>
        <translation>Der Wert %1 des Feldes „%2“ liegt außerhalb von %3..%4 (%5 Hex-Ziffern); verwenden Sie einen Wert in diesem Bereich.</translation>
    </message>
    <message>
        <source>Field &quot;%1&quot; needs a number, got &quot;%2&quot;.</source>
        <translation>Feld „%1“ braucht eine Zahl, erhalten: „%2“.</translation>
    </message>
    <message>
        <source>Field &quot;%1&quot; contains a NUL character; remove it.</source>
        <translation>Feld „%1“ enthält ein NUL-Zeichen; entfernen Sie es.</translation>
    </message>
    <message>
        <source>The text &quot;%1&quot; of field &quot;%2&quot; is %3 characters long; at most %4 fit.</source>
        <translation>Der Text „%1“ des Feldes „%2“ ist %3 Zeichen lang; höchstens %4 passen.</translation>
    </message>
    <message>
        <source>Field &quot;%1&quot; needs exactly %2 bytes, got %3.</source>
        <translation>Feld „%1“ braucht genau %2 Bytes, erhalten: %3.</translation>
    </message>
    <message>
        <source>Field &quot;%1&quot; needs exactly %2 words, got %3.</source>
        <translation>Feld „%1“ braucht genau %2 Wörter, erhalten: %3.</translation>
    </message>
    <message>
        <source>Field &quot;%1&quot; has an unknown type.</source>
        <translation>Feld „%1“ hat einen unbekannten Typ.</translation>
    </message>
    <message>
        <source>Malformed data: field &quot;%1&quot; at offset %2 %3.</source>
        <translation>Fehlerhafte Daten: Feld „%1“ an Stelle %2 %3.</translation>
    </message>
    <message>
        <source>has %1 characters, not a multiple of %2</source>
        <translation>hat %1 Zeichen, kein Vielfaches von %2</translation>
    </message>
    <message>
        <source>is not hexadecimal</source>
        <translation>ist nicht hexadezimal</translation>
    </message>
    <message>
        <source>has an odd number of digits</source>
        <translation>hat eine ungerade Zahl von Ziffern</translation>
    </message>
    <message>
        <source>%1: expected &quot;OK&quot;, got &quot;%2&quot;.</source>
        <translation>%1: „OK“ erwartet, erhalten: „%2“.</translation>
    </message>
    <message>
        <source>needs %1 characters, only %2 left</source>
        <translation>braucht %1 Zeichen, nur %2 übrig</translation>
    </message>
    <message>
        <source>Malformed data: %1 unexpected characters after the last field.</source>
        <translation>Fehlerhafte Daten: %1 unerwartete Zeichen nach dem letzten Feld.</translation>
    </message>
    <message>
        <source>Cannot send %1: %2</source>
        <translation>%1 kann nicht gesendet werden: %2</translation>
    </message>
    <message>
        <source>The request does not start with %1.</source>
        <translation>Die Anfrage beginnt nicht mit %1.</translation>
    </message>
    <message>
        <source>%1 has no data reply.</source>
        <translation>%1 hat keine Datenantwort.</translation>
    </message>
    <message>
        <source>Cannot answer %1: %2</source>
        <translation>%1 kann nicht beantwortet werden: %2</translation>
    </message>
    <message>
        <source>the device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <source>check the cable, the baud rate, that the device speaks the Multiuser protocol and the device number</source>
        <translation>prüfen Sie das Kabel, die Baudrate, dass das Gerät das Multiuser-Protokoll spricht, und die Gerätenummer</translation>
    </message>
    <message>
        <source>check the cable, the baud rate and that the device speaks the Standard protocol</source>
        <translation>prüfen Sie das Kabel, die Baudrate und dass das Gerät das Standard-Protokoll spricht</translation>
    </message>
    <message>
        <source>a reply with a wrong checksum</source>
        <translation>eine Antwort mit falscher Prüfsumme</translation>
    </message>
    <message>
        <source>an oversized reply</source>
        <translation>eine übergroße Antwort</translation>
    </message>
    <message>
        <source>a malformed reply: %1</source>
        <translation>eine fehlerhafte Antwort: %1</translation>
    </message>
    <message>
        <source>the device repeated an answer to an earlier request</source>
        <translation>das Gerät wiederholte die Antwort auf eine frühere Anfrage</translation>
    </message>
    <message>
        <source>%1 is not a command of the catalogue</source>
        <translation>%1 ist kein Befehl des Katalogs</translation>
    </message>
    <message>
        <source>%1: the device reported error %2: %3</source>
        <translation>%1: das Gerät meldete Fehler %2: %3</translation>
    </message>
    <message>
        <source>%1: the device does not know this command (firmware dated %2); it needs a newer firmware for it</source>
        <translation>%1: das Gerät kennt diesen Befehl nicht (Firmware vom %2); dafür braucht es eine neuere Firmware</translation>
    </message>
    <message>
        <source>a request starts with &apos;?&apos; or &apos;!&apos;, not &apos;%1&apos;</source>
        <translation>eine Anfrage beginnt mit &apos;?&apos; oder &apos;!&apos;, nicht mit &apos;%1&apos;</translation>
    </message>
    <message>
        <source>an empty request: type the command letters after %1</source>
        <translation>eine leere Anfrage: tippen Sie die Befehlsbuchstaben nach %1</translation>
    </message>
    <message>
        <source>an empty request: type ? or ! and the command</source>
        <translation>eine leere Anfrage: tippen Sie ? oder ! und den Befehl</translation>
    </message>
    <message>
        <source>CamCon ASCII, Multiuser (RS485 bus)</source>
        <translation>CamCon ASCII, Multiuser (RS485-Bus)</translation>
    </message>
    <message>
        <source>CamCon ASCII, Standard (RS232)</source>
        <translation>CamCon ASCII, Standard (RS232)</translation>
    </message>
    <message>
        <source>the %1 protocol got settings of %2</source>
        <translation>das Protokoll %1 erhielt Einstellungen von %2</translation>
    </message>
    <message>
        <source>another protocol</source>
        <translation>einem anderen Protokoll</translation>
    </message>
    <message>
        <source>reading the device identity (?EPROM)</source>
        <translation>Lesen der Gerätekennung (?EPROM)</translation>
    </message>
    <message>
        <source>reading the device identity (?%1)</source>
        <translation>Lesen der Gerätekennung (?%1)</translation>
    </message>
    <message>
        <source>reading the error state (?ERR)</source>
        <translation>Lesen des Fehlerzustands (?ERR)</translation>
    </message>
    <message>
        <source>reading the status (?%1)</source>
        <translation>Lesen des Zustands (?%1)</translation>
    </message>
    <message>
        <source>resetting the error (!ERR)</source>
        <translation>Zurücksetzen des Fehlers (!ERR)</translation>
    </message>
    <message>
        <source>selecting program %1 (!PAU)</source>
        <translation>Auswählen von Programm %1 (!PAU)</translation>
    </message>
    <message>
        <source>program %1, output %2</source>
        <translation>Programm %1, Ausgang %2</translation>
    </message>
    <message>
        <source>reading %1: the device reports more than %2 cams on one track; check the device</source>
        <translation>Lesen von %1: das Gerät meldet mehr als %2 Nocken auf einer Spur; prüfen Sie das Gerät</translation>
    </message>
    <message>
        <source>inserting the cam %1..%2 on %3 (!NINS)</source>
        <translation>Einfügen des Nockens %1..%2 in %3 (!NINS)</translation>
    </message>
    <message>
        <source> On an insert the usual cause is a cam that overlaps another cam of the track or lies outside the device&apos;s range.</source>
        <translation> Beim Einfügen ist die übliche Ursache ein Nocken, der einen anderen Nocken der Spur überlappt oder außerhalb des Bereichs des Geräts liegt.</translation>
    </message>
    <message>
        <source>deleting the cam at %1 on %2 (!NDEL)</source>
        <translation>Löschen des Nockens bei %1 in %2 (!NDEL)</translation>
    </message>
    <message>
        <source> Nothing had been changed on the track yet.</source>
        <translation> An der Spur war noch nichts geändert worden.</translation>
    </message>
    <message>
        <source> The cams already changed were put back: the track is as it was.</source>
        <translation> Die bereits geänderten Nocken wurden zurückgesetzt: die Spur ist wie vorher.</translation>
    </message>
    <message>
        <source> Putting the track back failed too: it may now hold other cams than before; read it to see.</source>
        <translation> Auch das Zurücksetzen der Spur schlug fehl: sie kann jetzt andere Nocken als vorher enthalten; lesen Sie sie, um es zu sehen.</translation>
    </message>
    <message>
        <source>writing %1: after lost replies the device holds %2 cams instead of the %3 written; write the track again</source>
        <translation>Schreiben von %1: nach verlorenen Antworten enthält das Gerät %2 Nocken statt der %3 geschriebenen; schreiben Sie die Spur erneut</translation>
    </message>
    <message>
        <source>deleting program %1 (!PDEL)</source>
        <translation>Löschen von Programm %1 (!PDEL)</translation>
    </message>
    <message>
        <source>copying program %1 to program %2 (!PCPY)</source>
        <translation>Kopieren von Programm %1 nach Programm %2 (!PCPY)</translation>
    </message>
    <message>
        <source>copying output %1 to output %2 in program %3 (!PACPY)</source>
        <translation>Kopieren von Ausgang %1 nach Ausgang %2 in Programm %3 (!PACPY)</translation>
    </message>
    <message>
        <source>reading the dead time of output %1 (?TZK)</source>
        <translation>Lesen der Totzeit von Ausgang %1 (?TZK)</translation>
    </message>
    <message>
        <source>writing the dead time of output %1 (!TZK)</source>
        <translation>Schreiben der Totzeit von Ausgang %1 (!TZK)</translation>
    </message>
    <message>
        <source>reading the name of output %1 (?ANAME)</source>
        <translation>Lesen des Namens von Ausgang %1 (?ANAME)</translation>
    </message>
    <message>
        <source>writing the name of output %1 (!ANAME)</source>
        <translation>Schreiben des Namens von Ausgang %1 (!ANAME)</translation>
    </message>
    <message>
        <source>reading the name of program %1 (?PNAME)</source>
        <translation>Lesen des Namens von Programm %1 (?PNAME)</translation>
    </message>
    <message>
        <source>writing the name of program %1 (!PNAME)</source>
        <translation>Schreiben des Namens von Programm %1 (!PNAME)</translation>
    </message>
    <message>
        <source>reading the settings (?%1)</source>
        <translation>Lesen der Einstellungen (?%1)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is no device setting</source>
        <translation>„%1“ ist keine Geräteeinstellung</translation>
    </message>
    <message>
        <source>reading user entry %1 (?USER)</source>
        <translation>Lesen von Benutzereintrag %1 (?USER)</translation>
    </message>
    <message>
        <source>reading the users: the device lists more than %1 entries and no end; check the device</source>
        <translation>Lesen der Benutzer: das Gerät nennt mehr als %1 Einträge und kein Ende; prüfen Sie das Gerät</translation>
    </message>
    <message>
        <source>writing user &quot;%1&quot; (!USER)</source>
        <translation>Schreiben von Benutzer „%1“ (!USER)</translation>
    </message>
    <message>
        <source>deleting a user (!USER)</source>
        <translation>Löschen eines Benutzers (!USER)</translation>
    </message>
    <message>
        <source>reading %1 (?GMXSPS)</source>
        <translation>Lesen von %1 (?GMXSPS)</translation>
    </message>
    <message>
        <source>writing %1 (!GMXSPS)</source>
        <translation>Schreiben von %1 (!GMXSPS)</translation>
    </message>
    <message>
        <source>reading the actual value of %1 (?SPSIST)</source>
        <translation>Lesen des Istwerts von %1 (?SPSIST)</translation>
    </message>
    <message>
        <source>reading the set value of %1 (?SPSSOLL)</source>
        <translation>Lesen des Sollwerts von %1 (?SPSSOLL)</translation>
    </message>
    <message>
        <source>reading EEPROM block %1 (?EE)</source>
        <translation>Lesen von EEPROM-Block %1 (?EE)</translation>
    </message>
    <message>
        <source>the device sent no EEPROM block 0000; check the device</source>
        <translation>das Gerät sandte keinen EEPROM-Block 0000; prüfen Sie das Gerät</translation>
    </message>
    <message>
        <source>asked for EEPROM block %1, the device sent block %2; try again</source>
        <translation>EEPROM-Block %1 angefragt, das Gerät sandte Block %2; versuchen Sie es erneut</translation>
    </message>
    <message>
        <source>the device sent a malformed EEPROM block: %1; try again</source>
        <translation>das Gerät sandte einen fehlerhaften EEPROM-Block: %1; versuchen Sie es erneut</translation>
    </message>
    <message>
        <source>the device sent EEPROM blocks up to FFFE without the end marker FFFF; check the device</source>
        <translation>das Gerät sandte EEPROM-Blöcke bis FFFE ohne die Endmarke FFFF; prüfen Sie das Gerät</translation>
    </message>
    <message>
        <source>the EEPROM image does not start with block 0000; nothing was sent</source>
        <translation>das EEPROM-Abbild beginnt nicht mit Block 0000; nichts wurde gesendet</translation>
    </message>
    <message>
        <source>The device may already be ERASED (block 0000 starts the erase).</source>
        <translation>Das Gerät ist möglicherweise bereits GELÖSCHT (Block 0000 startet das Löschen).</translation>
    </message>
    <message>
        <source>The device is now ERASED: it holds only the blocks before %1 and does not run.</source>
        <translation>Das Gerät ist jetzt GELÖSCHT: es enthält nur die Blöcke vor %1 und läuft nicht.</translation>
    </message>
    <message>
        <source>The device holds every block but did not confirm that it started.</source>
        <translation>Das Gerät enthält jeden Block, hat aber nicht bestätigt, dass es gestartet ist.</translation>
    </message>
    <message>
        <source>restore failed at EEPROM block %1 of %2 (!EE%3). %4 Running the same restore again is safe: it starts by erasing the device. Cause</source>
        <translation>Wiederherstellung bei EEPROM-Block %1 von %2 fehlgeschlagen (!EE%3). %4 Dieselbe Wiederherstellung erneut auszuführen ist sicher: sie beginnt mit dem Löschen des Geräts. Ursache</translation>
    </message>
    <message>
        <source>a bus scan needs the Multiuser protocol; connect with --protocol multiuser</source>
        <translation>eine Bussuche braucht das Multiuser-Protokoll; verbinden Sie mit --protocol multiuser</translation>
    </message>
    <message>
        <source>no reply</source>
        <translation>keine Antwort</translation>
    </message>
    <message>
        <source>1 attempt</source>
        <translation>1 Versuch</translation>
    </message>
    <message>
        <source>%1 attempts</source>
        <translation>%1 Versuchen</translation>
    </message>
    <message>
        <source>%1 from %2 to %3 on %4 after %5 of %6 ms; %7</source>
        <translation>%1 von %2 auf %3 an %4 nach %5 zu je %6 ms; %7</translation>
    </message>
    <message>
        <source>device %1</source>
        <translation>Gerät %1</translation>
    </message>
    <message>
        <source>reading %1 (?NF)</source>
        <translation>Lesen von %1 (?NF)</translation>
    </message>
    <message>
        <source>reading %1 (?NN)</source>
        <translation>Lesen von %1 (?NN)</translation>
    </message>
    <message>
        <source>reading %1 (?NS)</source>
        <translation>Lesen von %1 (?NS)</translation>
    </message>
    <message>
        <source>reading %1 (?%2)</source>
        <translation>Lesen von %1 (?%2)</translation>
    </message>
    <message>
        <source>writing %1 (!%2)</source>
        <translation>Schreiben von %1 (!%2)</translation>
    </message>
    <message>
        <source>Editing a program other than the active one exists only in %1.</source>
        <translation>Das Bearbeiten eines anderen als des aktiven Programms gibt es nur in %1.</translation>
    </message>
    <message>
        <source>a reply without a frame start</source>
        <translation>eine Antwort ohne Rahmenanfang</translation>
    </message>
    <message>
        <source>a reply that broke off before its end</source>
        <translation>eine Antwort, die vor ihrem Ende abbrach</translation>
    </message>
    <message>
        <source>restore: the device took every block but did not confirm that it started (!EE%1): %2. Run the same restore again. Cause</source>
        <translation>Wiederherstellung: das Gerät hat jeden Block angenommen, aber den Start nicht bestätigt (!EE%1): %2. Führen Sie dieselbe Wiederherstellung erneut aus. Ursache</translation>
    </message>
    <message>
        <source>the end block, sent again, failed</source>
        <translation>der erneut gesendete Endblock ist fehlgeschlagen</translation>
    </message>
    <message>
        <source>reading the EEPROM back failed</source>
        <translation>das Zurücklesen des EEPROMs ist fehlgeschlagen</translation>
    </message>
    <message>
        <source>its EEPROM differs from the image</source>
        <translation>sein EEPROM weicht vom Abbild ab</translation>
    </message>
    <message>
        <source>%1 blocks read back, %2 in the image</source>
        <translation>%1 Blöcke zurückgelesen, %2 im Abbild</translation>
    </message>
    <message>
        <source>Dead-time modes are data words 251..253, which 3964R e38 cannot address (words 0..127); set the device to 3964R n96 (--protocol 3964r-n96) to reach them.</source>
        <translation>Totzeit-Modi sind die Datenwörter 251..253, die 3964R e38 nicht adressieren kann (Wörter 0..127); stellen Sie das Gerät auf 3964R n96 (--protocol 3964r-n96), um sie zu erreichen.</translation>
    </message>
    <message>
        <source>writing to</source>
        <translation>Schreiben auf</translation>
    </message>
    <message>
        <source>the connection speaks %1, which does not reach this kind of device; connect with a protocol of its family</source>
        <translation>die Verbindung spricht %1, das diese Geräteart nicht erreicht; verbinden Sie mit einem Protokoll ihrer Familie</translation>
    </message>
    <message>
        <source>no connection</source>
        <translation>keine Verbindung</translation>
    </message>
    <message>
        <source>RK512 read of data area %1 at offset %2 (%3 16-bit words)</source>
        <translation>RK512-Lesen aus Datenbereich %1 ab Offset %2 (%3 16-Bit-Wörter)</translation>
    </message>
    <message>
        <source>RK512 write of data area %1 at offset %2 (%3 16-bit words)</source>
        <translation>RK512-Schreiben in Datenbereich %1 ab Offset %2 (%3 16-Bit-Wörter)</translation>
    </message>
    <message>
        <source>No error.</source>
        <translation>Kein Fehler.</translation>
    </message>
    <message>
        <source>Error 16, command unknown: the device serves only data blocks (&apos;D&apos;). The tool sent another block type; report this as a bug.</source>
        <translation>Fehler 16, Befehl unbekannt: das Gerät bedient nur Datenbausteine (&apos;D&apos;). Das Programm hat einen anderen Bausteintyp gesendet; melden Sie dies als Fehler.</translation>
    </message>
    <message>
        <source>Error 20, beyond the data block: the words asked for reach past the end of the data area, or the area does not exist on this device or firmware. Check the area and word numbers against the device&apos;s manual.</source>
        <translation>Fehler 20, außerhalb des Datenbausteins: die angefragten Wörter reichen über das Ende des Datenbereichs hinaus, oder der Bereich existiert auf diesem Gerät oder dieser Firmware nicht. Prüfen Sie Bereichs- und Wortnummern anhand des Gerätehandbuchs.</translation>
    </message>
    <message>
        <source>Error 22, command unknown: the device knows only read (&apos;E&apos;) and write (&apos;A&apos;). The tool sent another order; report this as a bug.</source>
        <translation>Fehler 22, Befehl unbekannt: das Gerät kennt nur Lesen (&apos;E&apos;) und Schreiben (&apos;A&apos;). Das Programm hat einen anderen Auftrag gesendet; melden Sie dies als Fehler.</translation>
    </message>
    <message>
        <source>Error 52, too many data: more than 128 bytes (64 16-bit words) in one telegram. Split the transfer into smaller telegrams.</source>
        <translation>Fehler 52, zu viele Daten: mehr als 128 Bytes (64 16-Bit-Wörter) in einem Telegramm. Teilen Sie die Übertragung in kleinere Telegramme auf.</translation>
    </message>
    <message>
        <source>Error 54, general error: the device refused the request, e.g. a write to a read-only word, a value out of range, or the EEPROM busy. Check the value and whether the word may be written, then try again.</source>
        <translation>Fehler 54, allgemeiner Fehler: das Gerät hat die Anfrage abgelehnt, z. B. Schreiben auf ein nur lesbares Wort, ein Wert außerhalb des Bereichs oder ein belegtes EEPROM. Prüfen Sie den Wert und ob das Wort geschrieben werden darf, und versuchen Sie es dann erneut.</translation>
    </message>
    <message>
        <source>Error %1, not listed in the manual: the device refused the request for a reason the tool does not know. Check the request and the device&apos;s display.</source>
        <translation>Fehler %1, nicht im Handbuch aufgeführt: das Gerät hat die Anfrage aus einem Grund abgelehnt, den das Programm nicht kennt. Prüfen Sie die Anfrage und die Anzeige des Geräts.</translation>
    </message>
    <message>
        <source>RK512: data area %1 does not exist (1..255).</source>
        <translation>RK512: Datenbereich %1 existiert nicht (1..255).</translation>
    </message>
    <message>
        <source>RK512: offset %1 does not fit in the offset byte (0..255); split the transfer or use 3964R n96.</source>
        <translation>RK512: Offset %1 passt nicht in das Offset-Byte (0..255); teilen Sie die Übertragung auf oder verwenden Sie 3964R n96.</translation>
    </message>
    <message>
        <source>RK512: %1 16-bit words in one telegram (%2..%3 allowed); split the transfer.</source>
        <translation>RK512: %1 16-Bit-Wörter in einem Telegramm (%2..%3 erlaubt); teilen Sie die Übertragung auf.</translation>
    </message>
    <message>
        <source>%1 carries %2 data bytes, %3 expected.</source>
        <translation>%1 enthält %2 Datenbytes, %3 erwartet.</translation>
    </message>
    <message>
        <source>%1: the reply is no RK512 reply (it must start with 00 00 00, got %2). Check that the device&apos;s serial mode is 3964R n96 or e38.</source>
        <translation>%1: die Antwort ist keine RK512-Antwort (sie muss mit 00 00 00 beginnen, erhalten: %2). Prüfen Sie, ob die serielle Betriebsart des Geräts 3964R n96 oder e38 ist.</translation>
    </message>
    <message>
        <source>%1: the reply carries %2 data bytes, %3 expected.</source>
        <translation>%1: die Antwort enthält %2 Datenbytes, %3 erwartet.</translation>
    </message>
    <message>
        <source>RK512: %1 data bytes do not make whole 32-bit table words.</source>
        <translation>RK512: %1 Datenbytes ergeben keine ganzen 32-Bit-Tabellenwörter.</translation>
    </message>
    <message>
        <source>Table transfer: data area %1 does not exist (1..255).</source>
        <translation>Tabellenübertragung: Datenbereich %1 existiert nicht (1..255).</translation>
    </message>
    <message>
        <source>Table transfer of %1 words from data area %2: nothing to transfer.</source>
        <translation>Tabellenübertragung von %1 Wörtern aus Datenbereich %2: nichts zu übertragen.</translation>
    </message>
    <message>
        <source>Table transfer: %1 words per telegram (1..%2 allowed).</source>
        <translation>Tabellenübertragung: %1 Wörter je Telegramm (1..%2 erlaubt).</translation>
    </message>
    <message>
        <source>Table transfer: words %1..%2 of data area %3 are outside the words 0..%4 that %5 can address.%6</source>
        <translation>Tabellenübertragung: die Wörter %1..%2 von Datenbereich %3 liegen außerhalb der Wörter 0..%4, die %5 adressieren kann.%6</translation>
    </message>
    <message>
        <source> Switch the device to 3964R n96 to reach them.</source>
        <translation> Stellen Sie das Gerät auf 3964R n96, um sie zu erreichen.</translation>
    </message>
    <message>
        <source>Cam %1 (%2..%3): 0x80000000 marks an empty cam on the device and cannot be a switch point; move the point by one.</source>
        <translation>Nocken %1 (%2..%3): 0x80000000 kennzeichnet auf dem Gerät einen leeren Nocken und kann kein Schaltpunkt sein; verschieben Sie den Punkt um eins.</translation>
    </message>
    <message>
        <source>Cam %1 switches on and off at %2: the device would delete it. Give it a length or remove it.</source>
        <translation>Nocken %1 schaltet bei %2 ein und aus: das Gerät würde ihn löschen. Geben Sie ihm eine Länge oder entfernen Sie ihn.</translation>
    </message>
    <message>
        <source>Cam %1 does not exist (1..%2).</source>
        <translation>Nocken %1 existiert nicht (1..%2).</translation>
    </message>
    <message>
        <source>A track holds at most %1 cams; this one has %2. Remove %3 cams.</source>
        <translation>Eine Spur fasst höchstens %1 Nocken; diese hat %2. Entfernen Sie %3 Nocken.</translation>
    </message>
    <message>
        <source>Track words must come in on/off pairs, at most %1; got %2 words.</source>
        <translation>Spurwörter müssen als Ein/Aus-Paare kommen, höchstens %1; erhalten: %2 Wörter.</translation>
    </message>
    <message>
        <source>Cam %1 reads %2..%3, which is no cam: the device&apos;s track data are inconsistent. Read the track again.</source>
        <translation>Nocken %1 lautet %2..%3, was kein Nocken ist: die Spurdaten des Geräts sind widersprüchlich. Lesen Sie die Spur erneut.</translation>
    </message>
    <message>
        <source>status query 0x01</source>
        <translation>Statusabfrage 0x01</translation>
    </message>
    <message>
        <source>error reset 0x02</source>
        <translation>Fehlerrücksetzung 0x02</translation>
    </message>
    <message>
        <source>program change 0x03</source>
        <translation>Programmwechsel 0x03</translation>
    </message>
    <message>
        <source>track read 0x04</source>
        <translation>Spur lesen 0x04</translation>
    </message>
    <message>
        <source>track write 0x05</source>
        <translation>Spur schreiben 0x05</translation>
    </message>
    <message>
        <source>dead-time read 0x06</source>
        <translation>Totzeit lesen 0x06</translation>
    </message>
    <message>
        <source>dead-time write 0x07</source>
        <translation>Totzeit schreiben 0x07</translation>
    </message>
    <message>
        <source>short command 0x%1</source>
        <translation>Kurzbefehl 0x%1</translation>
    </message>
    <message>
        <source>The cause of the error is still present; check the encoder and the outputs, then reset again.</source>
        <translation>Die Fehlerursache besteht weiter; prüfen Sie Geber und Ausgänge und setzen Sie dann erneut zurück.</translation>
    </message>
    <message>
        <source>Check that the program number is within the device&apos;s range.</source>
        <translation>Prüfen Sie, ob die Programmnummer im Bereich des Geräts liegt.</translation>
    </message>
    <message>
        <source>Check the program and output numbers, that the cams lie between the smallest and largest actual value, and that the device has room for them.</source>
        <translation>Prüfen Sie Programm- und Ausgangsnummern, ob die Nocken zwischen kleinstem und größtem Istwert liegen und ob das Gerät Platz für sie hat.</translation>
    </message>
    <message>
        <source>Check the output number and that the dead time does not exceed the device&apos;s largest dead time.</source>
        <translation>Prüfen Sie die Ausgangsnummer und ob die Totzeit die größte Totzeit des Geräts nicht überschreitet.</translation>
    </message>
    <message>
        <source>%1 %2 does not fit the byte of the short command (%3..255).</source>
        <translation>%1 %2 passt nicht in das Byte des Kurzbefehls (%3..255).</translation>
    </message>
    <message>
        <source>%1 %2 does not fit the 16-bit word of the short command (0..65535).</source>
        <translation>%1 %2 passt nicht in das 16-Bit-Wort des Kurzbefehls (0..65535).</translation>
    </message>
    <message>
        <source>The device does not know the %1 (it answered &quot;:Z&quot;); its firmware may not have it. Use the table interface (RK512) instead.</source>
        <translation>Das Gerät kennt den Befehl %1 nicht (es antwortete „:Z“); seine Firmware hat ihn möglicherweise nicht. Verwenden Sie stattdessen die Tabellenschnittstelle (RK512).</translation>
    </message>
    <message>
        <source>The reply to the %1 does not start with &apos;:&apos; and its number (got %2). Check that the device&apos;s serial mode is 3964R.</source>
        <translation>Die Antwort auf den Befehl %1 beginnt nicht mit &apos;:&apos; und seiner Nummer (erhalten: %2). Prüfen Sie, ob die serielle Betriebsart des Geräts 3964R ist.</translation>
    </message>
    <message>
        <source>The reply to the %1 has %2 bytes, %3 expected.</source>
        <translation>Die Antwort auf den Befehl %1 hat %2 Bytes, %3 erwartet.</translation>
    </message>
    <message>
        <source>%1 %2 does not fit the 16-bit word of the short commands (%3..%4); use the table interface (RK512).</source>
        <translation>%1 %2 passt nicht in das 16-Bit-Wort der Kurzbefehle (%3..%4); verwenden Sie die Tabellenschnittstelle (RK512).</translation>
    </message>
    <message>
        <source>Virtual inputs go in whole 16-bit words; give a multiple of 16 (got %1). Choose the extra bits with care: without the PLC logic module a 0 switches its output off.</source>
        <translation>Virtuelle Eingänge werden in ganzen 16-Bit-Wörtern übertragen; geben Sie ein Vielfaches von 16 an (erhalten: %1). Wählen Sie die zusätzlichen Bits mit Bedacht: ohne das SPS-Logikmodul schaltet eine 0 ihren Ausgang ab.</translation>
    </message>
    <message>
        <source>%1 virtual inputs do not fit one status query (at most %2).</source>
        <translation>%1 virtuelle Eingänge passen nicht in eine Statusabfrage (höchstens %2).</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Programm</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Ausgang</translation>
    </message>
    <message>
        <source>Cam count</source>
        <translation>Nockenanzahl</translation>
    </message>
    <message>
        <source>Output %1, cam %2: switch-on point</source>
        <translation>Ausgang %1, Nocken %2: Einschaltpunkt</translation>
    </message>
    <message>
        <source>Output %1, cam %2: switch-off point</source>
        <translation>Ausgang %1, Nocken %2: Ausschaltpunkt</translation>
    </message>
    <message>
        <source>The track write needs %1 bytes; a short command holds %2 (about 14 cams in all). Write fewer tracks per command, or use the table interface (RK512) for longer tracks.</source>
        <translation>Das Schreiben der Spuren braucht %1 Bytes; ein Kurzbefehl fasst %2 (insgesamt etwa 14 Nocken). Schreiben Sie weniger Spuren je Befehl oder verwenden Sie für längere Spuren die Tabellenschnittstelle (RK512).</translation>
    </message>
    <message>
        <source>Dead time (0.1 ms)</source>
        <translation>Totzeit (0,1 ms)</translation>
    </message>
    <message>
        <source>actual-value error %1</source>
        <translation>Istwertfehler %1</translation>
    </message>
    <message>
        <source>output error</source>
        <translation>Ausgangsfehler</translation>
    </message>
    <message>
        <source>unknown status %1</source>
        <translation>unbekannter Status %1</translation>
    </message>
    <message>
        <source>at least %1</source>
        <translation>mindestens %1</translation>
    </message>
    <message>
        <source>%1 for %2 outputs</source>
        <translation>%1 für %2 Ausgänge</translation>
    </message>
    <message>
        <source>The device refused the %1 (it answered &quot;ER&quot;). %2</source>
        <translation>Das Gerät hat den Befehl %1 abgelehnt (es antwortete „ER“). %2</translation>
    </message>
    <message>
        <source>The reply to the %1 is neither &quot;OK&quot; nor &quot;ER&quot; (got %2).</source>
        <translation>Die Antwort auf den Befehl %1 ist weder „OK“ noch „ER“ (erhalten: %2).</translation>
    </message>
    <message>
        <source>Asked for program %1, output %2; the reply is for program %3, output %4. Read the track again.</source>
        <translation>Angefragt: Programm %1, Ausgang %2; die Antwort gilt für Programm %3, Ausgang %4. Lesen Sie die Spur erneut.</translation>
    </message>
    <message>
        <source>%1 for %2 cams</source>
        <translation>%1 für %2 Nocken</translation>
    </message>
    <message>
        <source>Asked for the dead time of output %1; the reply is for output %2. Read it again.</source>
        <translation>Angefragt: Totzeit von Ausgang %1; die Antwort gilt für Ausgang %2. Lesen Sie sie erneut.</translation>
    </message>
    <message>
        <source>Actual value</source>
        <translation>Istwert</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>Output count</source>
        <translation>Ausgangsanzahl</translation>
    </message>
    <message>
        <source>%1 outputs do not fit one status reply.</source>
        <translation>%1 Ausgänge passen nicht in eine Statusantwort.</translation>
    </message>
    <message>
        <source>Switch-on point</source>
        <translation>Einschaltpunkt</translation>
    </message>
    <message>
        <source>Switch-off point</source>
        <translation>Ausschaltpunkt</translation>
    </message>
    <message>
        <source>%1 cams do not fit one track reply (at most 14).</source>
        <translation>%1 Nocken passen nicht in eine Spurantwort (höchstens 14).</translation>
    </message>
    <message>
        <source>the device (%1)</source>
        <translation>das Gerät (%1)</translation>
    </message>
    <message>
        <source>check the cable, that the device&apos;s serial mode (menu &quot;Ser:&quot;) is %1 and the line %2 8%3%4</source>
        <translation>prüfen Sie das Kabel, ob die serielle Betriebsart des Geräts (Menü „Ser:“) %1 ist und die Leitung %2 8%3%4</translation>
    </message>
    <message>
        <source>a telegram before the device took the request</source>
        <translation>ein Telegramm, bevor das Gerät die Anfrage angenommen hat</translation>
    </message>
    <message>
        <source>3964R handshake, or a block answered with NAK</source>
        <translation>3964R-Quittierung oder ein mit NAK beantworteter Block</translation>
    </message>
    <message>
        <source>RK512 read of area %1, offset %2 (1 word)</source>
        <translation>RK512-Lesen aus Bereich %1, Offset %2 (1 Wort)</translation>
    </message>
    <message>
        <source>RK512 write of area %1, offset %2 (1 word)</source>
        <translation>RK512-Schreiben in Bereich %1, Offset %2 (1 Wort)</translation>
    </message>
    <message>
        <source>RK512 read of area %1, offset %2 (%3 words)</source>
        <translation>RK512-Lesen aus Bereich %1, Offset %2 (%3 Wörter)</translation>
    </message>
    <message>
        <source>RK512 write of area %1, offset %2 (%3 words)</source>
        <translation>RK512-Schreiben in Bereich %1, Offset %2 (%3 Wörter)</translation>
    </message>
    <message>
        <source>a telegram that is no RK512 reply</source>
        <translation>ein Telegramm, das keine RK512-Antwort ist</translation>
    </message>
    <message>
        <source>an RK512 reply of %1 bytes</source>
        <translation>eine RK512-Antwort mit %1 Bytes</translation>
    </message>
    <message>
        <source>%1: empty telegram</source>
        <translation>%1: leeres Telegramm</translation>
    </message>
    <message>
        <source>a telegram that answers another command</source>
        <translation>ein Telegramm, das einen anderen Befehl beantwortet</translation>
    </message>
    <message>
        <source>output %1 does not exist in the table interface (outputs %2..%3)</source>
        <translation>Ausgang %1 existiert in der Tabellenschnittstelle nicht (Ausgänge %2..%3)</translation>
    </message>
    <message>
        <source>reading the device identity (data area %1)</source>
        <translation>Lesen der Gerätekennung (Datenbereich %1)</translation>
    </message>
    <message>
        <source>reading the actual value</source>
        <translation>Lesen des Istwerts</translation>
    </message>
    <message>
        <source>reading the status (0x01)</source>
        <translation>Lesen des Zustands (0x01)</translation>
    </message>
    <message>
        <source>reading the inputs</source>
        <translation>Lesen der Eingänge</translation>
    </message>
    <message>
        <source>resetting the error (0x02)</source>
        <translation>Rücksetzen des Fehlers (0x02)</translation>
    </message>
    <message>
        <source>selecting program %1 (0x03)</source>
        <translation>Anwählen von Programm %1 (0x03)</translation>
    </message>
    <message>
        <source>selecting program %1 for programming (data area %2)</source>
        <translation>Anwählen von Programm %1 zum Programmieren (Datenbereich %2)</translation>
    </message>
    <message>
        <source>the device reports %1 %2, which no track holds (0..%3); check the device</source>
        <translation>das Gerät meldet %1 %2, was keine Spur fasst (0..%3); prüfen Sie das Gerät</translation>
    </message>
    <message>
        <source>the device reports %1 %2 but its places hold %3; read again, and check the device if this persists</source>
        <translation>das Gerät meldet %1 %2, aber seine Plätze enthalten %3; lesen Sie erneut und prüfen Sie das Gerät, falls dies bleibt</translation>
    </message>
    <message>
        <source>all %1 places that %2 reaches hold %3, so there may be more; read them over 3964R n96 (--protocol 3964r-n96)</source>
        <translation>alle %1 Plätze, die %2 erreicht, enthalten %3, es kann also mehr geben; lesen Sie sie über 3964R n96 (--protocol 3964r-n96)</translation>
    </message>
    <message>
        <source>the device may still hold the old %1 or already the first of the new ones; read it to see, or write it again</source>
        <translation>das Gerät kann noch die alten %1 oder schon die ersten der neuen enthalten; lesen Sie nach oder schreiben Sie erneut</translation>
    </message>
    <message>
        <source>the device now holds only the first %1 of the %2 %3 written (the old ones are gone); write it again</source>
        <translation>das Gerät enthält jetzt nur die ersten %1 der %2 geschriebenen %3 (die alten sind weg); schreiben Sie erneut</translation>
    </message>
    <message>
        <source>cams</source>
        <translation>Nocken</translation>
    </message>
    <message>
        <source>reading %1</source>
        <translation>Lesen von %1</translation>
    </message>
    <message>
        <source>reading program %1</source>
        <translation>Lesen von Programm %1</translation>
    </message>
    <message>
        <source>writing %1</source>
        <translation>Schreiben von %1</translation>
    </message>
    <message>
        <source>%1: %2 cams, but over %3 a track can hold at most %4 (the places it reaches); use 3964R n96 (--protocol 3964r-n96)</source>
        <translation>%1: %2 Nocken, aber über %3 fasst eine Spur höchstens %4 (die Plätze, die es erreicht); verwenden Sie 3964R n96 (--protocol 3964r-n96)</translation>
    </message>
    <message>
        <source>deleting program %1</source>
        <translation>Löschen von Programm %1</translation>
    </message>
    <message>
        <source>copying program %1 to program %2</source>
        <translation>Kopieren von Programm %1 nach Programm %2</translation>
    </message>
    <message>
        <source>reading the dead time of output %1</source>
        <translation>Lesen der Totzeit von Ausgang %1</translation>
    </message>
    <message>
        <source>writing the dead time of output %1</source>
        <translation>Schreiben der Totzeit von Ausgang %1</translation>
    </message>
    <message>
        <source>reading the dead-time mode of output %1</source>
        <translation>Lesen des Totzeit-Modus von Ausgang %1</translation>
    </message>
    <message>
        <source>%1: the device reports mode %2, which the manual does not list (0, 1, 2); check the device</source>
        <translation>%1: das Gerät meldet Modus %2, den das Handbuch nicht aufführt (0, 1, 2); prüfen Sie das Gerät</translation>
    </message>
    <message>
        <source>writing the dead-time mode of output %1</source>
        <translation>Schreiben des Totzeit-Modus von Ausgang %1</translation>
    </message>
    <message>
        <source>reading the settings (data area %1)</source>
        <translation>Lesen der Einstellungen (Datenbereich %1)</translation>
    </message>
    <message>
        <source>%1 (device value %2)</source>
        <translation>%1 (Gerätewert %2)</translation>
    </message>
    <message>
        <source>%1 (no data word in the table interface)</source>
        <translation>%1 (kein Datenwort in der Tabellenschnittstelle)</translation>
    </message>
    <message>
        <source>%1 (a value the settings cannot show)</source>
        <translation>%1 (ein Wert, den die Einstellungen nicht anzeigen können)</translation>
    </message>
    <message>
        <source>the parameters of special encoder types other than the selected type %1 (the device keeps only those of one type)</source>
        <translation>die Parameter anderer Sondergeber-Typen als des gewählten Typs %1 (das Gerät behält nur die eines Typs)</translation>
    </message>
    <message>
        <source>%1 cannot be written over the table interface (no data word); leave them out. Nothing was written.</source>
        <translation>%1 kann über die Tabellenschnittstelle nicht geschrieben werden (kein Datenwort); lassen Sie sie weg. Es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>writing the special encoder of type %1</source>
        <translation>Schreiben des Sondergebers vom Typ %1</translation>
    </message>
    <message>
        <source>writing the settings (data area %1)</source>
        <translation>Schreiben der Einstellungen (Datenbereich %1)</translation>
    </message>
    <message>
        <source>%1: the device holds %2, which the settings cannot show</source>
        <translation>%1: das Gerät enthält %2, was die Einstellungen nicht anzeigen können</translation>
    </message>
    <message>
        <source>%1: the device&apos;s special encoder is of type %2, and it keeps the parameters of that type only</source>
        <translation>%1: der Sondergeber des Geräts ist vom Typ %2, und es behält nur die Parameter dieses Typs</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is no setting the table interface has a data word for</source>
        <translation>„%1“ ist keine Einstellung, für die die Tabellenschnittstelle ein Datenwort hat</translation>
    </message>
    <message>
        <source>%1 does not exist (areas O, P, M, X; numbers from 0)</source>
        <translation>%1 existiert nicht (Bereiche O, P, M, X; Nummern ab 0)</translation>
    </message>
    <message>
        <source>reading the actual value of %1</source>
        <translation>Lesen des Istwerts von %1</translation>
    </message>
    <message>
        <source>reading the set value of %1</source>
        <translation>Lesen des Sollwerts von %1</translation>
    </message>
    <message>
        <source>reading the analogue cams of analogue output %1</source>
        <translation>Lesen der Analognocken von Analogausgang %1</translation>
    </message>
    <message>
        <source>%1: analogue outputs are 1..%2</source>
        <translation>%1: Analogausgänge sind 1..%2</translation>
    </message>
    <message>
        <source>base points</source>
        <translation>Stützpunkte</translation>
    </message>
    <message>
        <source>writing the analogue cams of analogue output %1</source>
        <translation>Schreiben der Analognocken von Analogausgang %1</translation>
    </message>
    <message>
        <source>%1: %2 base points, but over %3 at most %4 fit</source>
        <translation>%1: %2 Stützpunkte, aber über %3 passen höchstens %4</translation>
    </message>
    <message>
        <source>reading the programming program</source>
        <translation>Lesen des Programmierprogramms</translation>
    </message>
    <message>
        <source>writing the programming program</source>
        <translation>Schreiben des Programmierprogramms</translation>
    </message>
    <message>
        <source>reading the EEPROM lock</source>
        <translation>Lesen der EEPROM-Sperre</translation>
    </message>
    <message>
        <source>locking the EEPROM</source>
        <translation>Sperren des EEPROMs</translation>
    </message>
    <message>
        <source>unlocking the EEPROM</source>
        <translation>Entsperren des EEPROMs</translation>
    </message>
    <message>
        <source>CamCon table interface, %1 (%2 8%3%4)</source>
        <translation>CamCon-Tabellenschnittstelle, %1 (%2 8%3%4)</translation>
    </message>
    <message>
        <source>the %1 protocol got settings of another protocol</source>
        <translation>das Protokoll %1 hat Einstellungen eines anderen Protokolls erhalten</translation>
    </message>
    <message>
        <source>3964R: a telegram is still being sent; wait for its end before sending the next one.</source>
        <translation>3964R: ein Telegramm wird noch gesendet; warten Sie sein Ende ab, bevor Sie das nächste senden.</translation>
    </message>
    <message>
        <source>3964R: a telegram of %1 bytes cannot be sent (1..%2 bytes allowed).</source>
        <translation>3964R: ein Telegramm mit %1 Bytes kann nicht gesendet werden (1..%2 Bytes erlaubt).</translation>
    </message>
    <message>
        <source>no DLE within %1 ms after STX</source>
        <translation>kein DLE innerhalb von %1 ms nach STX</translation>
    </message>
    <message>
        <source>no DLE within %1 ms after the block</source>
        <translation>kein DLE innerhalb von %1 ms nach dem Block</translation>
    </message>
    <message>
        <source>%1 instead of DLE after STX</source>
        <translation>%1 statt DLE nach STX</translation>
    </message>
    <message>
        <source>NAK after the block (the partner found it bad)</source>
        <translation>NAK nach dem Block (der Partner hat ihn als fehlerhaft erkannt)</translation>
    </message>
    <message>
        <source>STX instead of DLE after the block</source>
        <translation>STX statt DLE nach dem Block</translation>
    </message>
    <message>
        <source>%1 instead of DLE after the block</source>
        <translation>%1 statt DLE nach dem Block</translation>
    </message>
    <message>
        <source>3964R: %1; the device may have executed the telegram, which must not be sent twice. Read back what it changes before trying again.</source>
        <translation>3964R: %1; das Gerät hat das Telegramm möglicherweise ausgeführt, und es darf nicht zweimal gesendet werden. Lesen Sie zurück, was es ändert, bevor Sie es erneut versuchen.</translation>
    </message>
    <message>
        <source>3964R: the partner did not acknowledge the telegram in %1 attempts (last: %2). Check the cable and that the device&apos;s serial mode is 3964R with the same baud rate and parity (n96: 9600 8N1, e38: 38400 8E1).</source>
        <translation>3964R: der Partner hat das Telegramm in %1 Versuchen nicht quittiert (zuletzt: %2). Prüfen Sie das Kabel und ob die serielle Betriebsart des Geräts 3964R mit derselben Baudrate und Parität ist (n96: 9600 8N1, e38: 38400 8E1).</translation>
    </message>
    <message>
        <source>permission denied on %1 (%2): this user may not open the serial port, or another program holds it. On Linux, add the user to the group dialout (sudo usermod -aG dialout $USER), then log out and in again; close any other program that uses the port.</source>
        <translation>Zugriff verweigert auf %1 (%2): Dieser Benutzer darf die serielle Schnittstelle nicht öffnen, oder ein anderes Programm belegt sie. Unter Linux nehmen Sie den Benutzer in die Gruppe dialout auf (sudo usermod -aG dialout $USER) und melden sich dann ab und wieder an; schließen Sie jedes andere Programm, das die Schnittstelle benutzt.</translation>
    </message>
    <message>
        <source>The short commands of the S7-CP340 coupling exist only in %1.</source>
        <translation>Die Kurzbefehle der S7-CP340-Kopplung gibt es nur in %1.</translation>
    </message>
    <message>
        <source>the end of the list</source>
        <translation>dem Ende der Liste</translation>
    </message>
    <message>
        <source>the start of the list</source>
        <translation>dem Anfang der Liste</translation>
    </message>
    <message>
        <source>user &quot;%1&quot;</source>
        <translation>Benutzer „%1“</translation>
    </message>
    <message>
        <source>between %1 and %2</source>
        <translation>zwischen %1 und %2</translation>
    </message>
    <message>
        <source>and %1 more places</source>
        <translation>und %1 weiteren Stellen</translation>
    </message>
    <message>
        <source>reading the users: the list changed while it was read (near %1); nothing is shown; read it again</source>
        <translation>Lesen der Benutzer: die Liste hat sich beim Lesen geändert (bei %1); nichts wird gezeigt; lesen Sie erneut</translation>
    </message>
    <message>
        <source>reading the users: after %1 walks through the list, %2 users were seen but one may still be missing %3; the list may be incomplete, so none is shown; check the cable and try again</source>
        <translation>Lesen der Benutzer: nach %1 Durchläufen durch die Liste wurden %2 Benutzer gesehen, aber es kann noch einer fehlen %3; die Liste kann unvollständig sein, darum wird keiner gezeigt; prüfen Sie das Kabel und versuchen Sie es erneut</translation>
    </message>
    <message>
        <source>reading output %1 of program %2 (0x04)</source>
        <translation>Lesen von Ausgang %1 in Programm %2 (0x04)</translation>
    </message>
    <message>
        <source>writing output %1 of program %2 (0x05)</source>
        <translation>Schreiben von Ausgang %1 in Programm %2 (0x05)</translation>
    </message>
    <message>
        <source>reading the dead time of output %1 (0x06)</source>
        <translation>Lesen der Totzeit von Ausgang %1 (0x06)</translation>
    </message>
    <message>
        <source>writing the dead time of output %1 (0x07)</source>
        <translation>Schreiben der Totzeit von Ausgang %1 (0x07)</translation>
    </message>
    <message>
        <source>the CamCon ASCII protocol (Standard or Multiuser)</source>
        <translation>dem CamCon-ASCII-Protokoll (Standard oder Multiuser)</translation>
    </message>
    <message>
        <source>the CamCon table interface (3964R n96 or e38)</source>
        <translation>der CamCon-Tabellenschnittstelle (3964R n96 oder e38)</translation>
    </message>
    <message>
        <source>CamCon, EPROM %1, device %2, %3 outputs, %4 programs</source>
        <translation>CamCon, EPROM %1, Gerät %2, %3 Ausgänge, %4 Programme</translation>
    </message>
    <message>
        <source>this protocol has no bus to scan</source>
        <translation>dieses Protokoll hat keinen Bus zum Absuchen</translation>
    </message>
    <message>
        <source>the %1</source>
        <translation>die %1</translation>
    </message>
    <message>
        <source>check the cable (MC100: RxD/TxD crossed; MC200: 1:1, and DTR high, RTS low power its interface), the baud rate (MC100: 9600) and the controller&apos;s variant</source>
        <translation>prüfen Sie das Kabel (MC100: RxD/TxD gekreuzt; MC200: 1:1, und DTR high, RTS low versorgen seine Schnittstelle), die Baudrate (MC100: 9600) und die Variante der Steuerung</translation>
    </message>
    <message>
        <source>PLC program present</source>
        <translation>SPS-Programm vorhanden</translation>
    </message>
    <message>
        <source>PLC program running</source>
        <translation>SPS-Programm läuft</translation>
    </message>
    <message>
        <source>error: invalid opcode</source>
        <translation>Fehler: ungültiger Opcode</translation>
    </message>
    <message>
        <source>error: stack overflow</source>
        <translation>Fehler: Stacküberlauf</translation>
    </message>
    <message>
        <source>breakpoint list cleared</source>
        <translation>Haltepunktliste gelöscht</translation>
    </message>
    <message>
        <source>task switching off</source>
        <translation>Taskumschaltung aus</translation>
    </message>
    <message>
        <source>current bit result 1</source>
        <translation>aktuelles Bitergebnis 1</translation>
    </message>
    <message>
        <source>PLC program at a breakpoint</source>
        <translation>SPS-Programm steht auf Haltepunkt</translation>
    </message>
    <message>
        <source>no PLC program</source>
        <translation>kein SPS-Programm</translation>
    </message>
    <message>
        <source>running, PC %1</source>
        <translation>läuft, PC %1</translation>
    </message>
    <message>
        <source>stopped, PC %1</source>
        <translation>angehalten, PC %1</translation>
    </message>
    <message>
        <source>start the PLC program</source>
        <translation>SPS-Programm starten</translation>
    </message>
    <message>
        <source>stop the PLC program</source>
        <translation>SPS-Programm anhalten</translation>
    </message>
    <message>
        <source>run one step of the PLC program</source>
        <translation>einen Schritt des SPS-Programms ausführen</translation>
    </message>
    <message>
        <source>reset the controller</source>
        <translation>Steuerung zurücksetzen</translation>
    </message>
    <message>
        <source>save to flash</source>
        <translation>in Flash sichern</translation>
    </message>
    <message>
        <source>load from flash</source>
        <translation>aus Flash laden</translation>
    </message>
    <message>
        <source>axis %1 is moving to %2 (now at %3)</source>
        <translation>Achse %1 fährt nach %2 (jetzt bei %3)</translation>
    </message>
    <message>
        <source>axis %1 stands at %2</source>
        <translation>Achse %1 steht bei %2</translation>
    </message>
    <message>
        <source>, axis error</source>
        <translation>, Achsfehler</translation>
    </message>
    <message>
        <source>home axis %1</source>
        <translation>Referenzfahrt Achse %1</translation>
    </message>
    <message>
        <source>move axis %1 to %2</source>
        <translation>Achse %1 nach %2 fahren</translation>
    </message>
    <message>
        <source>move axis %1 by %2</source>
        <translation>Achse %1 um %2 fahren</translation>
    </message>
    <message>
        <source>move axis %1 continuously in the plus direction</source>
        <translation>Achse %1 endlos in Plusrichtung fahren</translation>
    </message>
    <message>
        <source>move axis %1 continuously in the minus direction</source>
        <translation>Achse %1 endlos in Minusrichtung fahren</translation>
    </message>
    <message>
        <source>stop axis %1</source>
        <translation>Achse %1 anhalten</translation>
    </message>
    <message>
        <source>stop axis %1 with the maximum ramp</source>
        <translation>Achse %1 mit maximaler Rampe anhalten</translation>
    </message>
    <message>
        <source>acknowledge the error of axis %1</source>
        <translation>Fehler von Achse %1 quittieren</translation>
    </message>
    <message>
        <source>set the speed of axis %1 to %2</source>
        <translation>Geschwindigkeit von Achse %1 auf %2 setzen</translation>
    </message>
    <message>
        <source>no MC100/MC200 answers reading variable 1: %1</source>
        <translation>keine MC100/MC200 antwortet auf das Lesen von Variable 1: %1</translation>
    </message>
    <message>
        <source>probed</source>
        <translation>abgefragt</translation>
    </message>
    <message>
        <source>the connection is set to the %1, but the controller answers as an %2 (variables of %3 bits): choose %2 or automatic detection</source>
        <translation>die Verbindung ist auf die %1 eingestellt, aber die Steuerung antwortet als %2 (Variablen mit %3 Bit): wählen Sie %2 oder die automatische Erkennung</translation>
    </message>
    <message>
        <source>as given, confirmed by the probe</source>
        <translation>wie angegeben, von der Abfrage bestätigt</translation>
    </message>
    <message>
        <source>as given (the probe found the %1)</source>
        <translation>wie angegeben (die Abfrage fand die %1)</translation>
    </message>
    <message>
        <source>the %1 cannot %2 (%3)</source>
        <translation>%2 ist mit der %1 nicht möglich (%3)</translation>
    </message>
    <message>
        <source>the memory telegrams need an MC200</source>
        <translation>die Speichertelegramme brauchen eine MC200</translation>
    </message>
    <message>
        <source>this needs an MC200 V2</source>
        <translation>das braucht eine MC200 V2</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>PLC program %1</source>
        <translation>SPS-Programm %1</translation>
    </message>
    <message>
        <source>variable numbers are 0 to 65535, not %1</source>
        <translation>Variablennummern sind 0 bis 65535, nicht %1</translation>
    </message>
    <message>
        <source>V%1 of the %2 holds %3 to %4 (%5 bits), not %6</source>
        <translation>V%1 der %2 fasst %3 bis %4 (%5 Bit), nicht %6</translation>
    </message>
    <message>
        <source>%1 is an input: inputs are read-only</source>
        <translation>%1 ist ein Eingang: Eingänge sind nur lesbar</translation>
    </message>
    <message>
        <source>reading it failed too: %1</source>
        <translation>auch das Lesen schlug fehl: %1</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%2 %1</translation>
    </message>
    <message>
        <source>set</source>
        <translation>setzen</translation>
    </message>
    <message>
        <source>clear</source>
        <translation>löschen</translation>
    </message>
    <message>
        <source>the answer to &quot;%1&quot; was lost (%2); it was not sent again, because it acts each time it arrives. Read back: %3</source>
        <translation>die Antwort auf &quot;%1&quot; ging verloren (%2); der Befehl wurde nicht erneut gesendet, weil er bei jedem Eintreffen wirkt. Zurückgelesen: %3</translation>
    </message>
    <message>
        <source>report its program status</source>
        <translation>Programmstatus melden</translation>
    </message>
    <message>
        <source>reading the status failed too: %1</source>
        <translation>auch das Lesen des Status schlug fehl: %1</translation>
    </message>
    <message>
        <source>report its axes</source>
        <translation>Achsen melden</translation>
    </message>
    <message>
        <source>axes are %1 to %2, not %3</source>
        <translation>Achsen sind %1 bis %2, nicht %3</translation>
    </message>
    <message>
        <source>a speed must be more than 0, not %1</source>
        <translation>eine Geschwindigkeit muss größer als 0 sein, nicht %1</translation>
    </message>
    <message>
        <source>the move may have started: %1</source>
        <translation>die Bewegung hat womöglich begonnen: %1</translation>
    </message>
    <message>
        <source>reading the axis failed too: %1</source>
        <translation>auch das Lesen der Achse schlug fehl: %1</translation>
    </message>
    <message>
        <source>read memory</source>
        <translation>Speicher lesen</translation>
    </message>
    <message>
        <source>memory is 0x0000 to 0xFFFF: %1 bytes from 0x%2 do not fit</source>
        <translation>der Speicher reicht von 0x0000 bis 0xFFFF: %1 Bytes ab 0x%2 passen nicht</translation>
    </message>
    <message>
        <source>write memory</source>
        <translation>Speicher schreiben</translation>
    </message>
    <message>
        <source>MC-1 (RS232)</source>
        <translation>MC-1 (RS232)</translation>
    </message>
    <message>
        <source>no 0xFF synchronisation byte from the MC100MA for %1 ms</source>
        <translation>kein 0xFF-Synchronisationsbyte von der MC100MA seit %1 ms</translation>
    </message>
    <message>
        <source>MC100 ASCII (RS232)</source>
        <translation>MC100 ASCII (RS232)</translation>
    </message>
    <message>
        <source>the MC100 (ASCII protocol)</source>
        <translation>die MC100 (ASCII-Protokoll)</translation>
    </message>
    <message>
        <source>check the cable (RxD/TxD crossed), 9600 baud, and that the MC100 speaks ASCII (a controller set to the binary protocol answers only that: connect with mc1)</source>
        <translation>prüfen Sie das Kabel (RxD/TxD gekreuzt), 9600 Baud und ob die MC100 ASCII spricht (eine auf das Binärprotokoll eingestellte Steuerung antwortet nur darauf: verbinden Sie mit mc1)</translation>
    </message>
    <message>
        <source>ASCII protocol, which looks alike on V1 and V2</source>
        <translation>ASCII-Protokoll, das auf V1 und V2 gleich aussieht</translation>
    </message>
    <message>
        <source>no MC100 answers in ASCII reading V1: %1</source>
        <translation>keine MC100 antwortet in ASCII auf das Lesen von V1: %1</translation>
    </message>
    <message>
        <source>MC100 (ASCII protocol)</source>
        <translation>MC100 (ASCII-Protokoll)</translation>
    </message>
    <message>
        <source>V%1 of the MC100 holds %2 to %3 (24 bits), not %4</source>
        <translation>V%1 der MC100 fasst %2 bis %3 (24 Bit), nicht %4</translation>
    </message>
    <message>
        <source>external RAM page %1 (only the flags&apos;)</source>
        <translation>externe RAM-Seite %1 (nur die der Merker)</translation>
    </message>
    <message>
        <source>the MC100&apos;s ASCII protocol has no requests for %1; an MC200 V2 over the binary protocol (mc1) has</source>
        <translation>das ASCII-Protokoll der MC100 hat keine Anfragen für: %1; eine MC200 V2 über das Binärprotokoll (mc1) hat sie</translation>
    </message>
    <message>
        <source>the program status</source>
        <translation>den Programmstatus</translation>
    </message>
    <message>
        <source>axes</source>
        <translation>Achsen</translation>
    </message>
    <message>
        <source>memory</source>
        <translation>Speicher</translation>
    </message>
    <message>
        <source>the answer &quot;%1&quot; holds a byte that is no printable ASCII (0x%2)</source>
        <translation>die Antwort „%1“ enthält ein Byte, das kein druckbares ASCII ist (0x%2)</translation>
    </message>
    <message>
        <source>the answer &quot;%1&quot; is no error number (! and four hex digits)</source>
        <translation>die Antwort „%1“ ist keine Fehlernummer (! und vier Hex-Ziffern)</translation>
    </message>
    <message>
        <source>the answer is an empty line</source>
        <translation>die Antwort ist eine leere Zeile</translation>
    </message>
    <message>
        <source>the drive refused %1 with %2 (an error number CamBench does not know: see the drive&apos;s manual)</source>
        <translation>der Antrieb lehnte %1 mit %2 ab (eine Fehlernummer, die CamBench nicht kennt: siehe Handbuch des Antriebs)</translation>
    </message>
    <message>
        <source>the drive refused %1 with %2 (%3)</source>
        <translation>der Antrieb lehnte %1 mit %2 ab (%3)</translation>
    </message>
    <message>
        <source>the Compax3 (RS232)</source>
        <translation>der Compax3 (RS232)</translation>
    </message>
    <message>
        <source>the Compax3 at address %1 (RS485)</source>
        <translation>der Compax3 an Adresse %1 (RS485)</translation>
    </message>
    <message>
        <source>check the cable (a null-modem cable with RTS/CTS), the baud rate (115200 unless set otherwise in the C3 ServoManager) and that the drive is powered</source>
        <translation>prüfen Sie das Kabel (ein Nullmodemkabel mit RTS/CTS), die Baudrate (115200, sofern im C3 ServoManager nicht anders eingestellt) und ob der Antrieb eingeschaltet ist</translation>
    </message>
    <message>
        <source>check the RS485 wiring, the baud rate and the drive&apos;s address (C3 ServoManager, &quot;RS485 settings&quot;); `c3 scan` lists the addresses that answer</source>
        <translation>prüfen Sie die RS485-Verdrahtung, die Baudrate und die Adresse des Antriebs (C3 ServoManager, „RS485 Einstellungen“); `c3 scan` listet die Adressen, die antworten</translation>
    </message>
    <message>
        <source>input I%1</source>
        <translation>Eingang I%1</translation>
    </message>
    <message>
        <source>no error</source>
        <translation>kein Fehler</translation>
    </message>
    <message>
        <source>position reached</source>
        <translation>Position erreicht</translation>
    </message>
    <message>
        <source>powerless</source>
        <translation>stromlos</translation>
    </message>
    <message>
        <source>powered standstill</source>
        <translation>bestromter Stillstand</translation>
    </message>
    <message>
        <source>zero known</source>
        <translation>Nullpunkt bekannt</translation>
    </message>
    <message>
        <source>PSB0</source>
        <translation>PSB0</translation>
    </message>
    <message>
        <source>PSB1</source>
        <translation>PSB1</translation>
    </message>
    <message>
        <source>PSB2</source>
        <translation>PSB2</translation>
    </message>
    <message>
        <source>motor temperature (%1)</source>
        <translation>Motortemperatur (%1)</translation>
    </message>
    <message>
        <source>following error (%1)</source>
        <translation>Schleppfehler (%1)</translation>
    </message>
    <message>
        <source>end limit + (%1)</source>
        <translation>Endlage + (%1)</translation>
    </message>
    <message>
        <source>end limit − (%1)</source>
        <translation>Endlage − (%1)</translation>
    </message>
    <message>
        <source>direction change while moving (%1)</source>
        <translation>Richtungswechsel während der Fahrt (%1)</translation>
    </message>
    <message>
        <source>error %1 (%2): see the drive&apos;s manual</source>
        <translation>Fehler %1 (%2): siehe Handbuch des Antriebs</translation>
    </message>
    <message>
        <source>powerless at %1</source>
        <translation>stromlos bei %1</translation>
    </message>
    <message>
        <source>moving, now at %1</source>
        <translation>fährt, jetzt bei %1</translation>
    </message>
    <message>
        <source>power the axis and acknowledge errors</source>
        <translation>die Achse bestromen und Fehler quittieren</translation>
    </message>
    <message>
        <source>switch the axis powerless</source>
        <translation>die Achse stromlos schalten</translation>
    </message>
    <message>
        <source>jog the axis in + direction</source>
        <translation>die Achse in +-Richtung tippen</translation>
    </message>
    <message>
        <source>jog the axis in − direction</source>
        <translation>die Achse in −-Richtung tippen</translation>
    </message>
    <message>
        <source>stop the axis</source>
        <translation>die Achse anhalten</translation>
    </message>
    <message>
        <source>target %1</source>
        <translation>Ziel %1</translation>
    </message>
    <message>
        <source>velocity %1</source>
        <translation>Geschwindigkeit %1</translation>
    </message>
    <message>
        <source>acceleration %1</source>
        <translation>Beschleunigung %1</translation>
    </message>
    <message>
        <source>start homing (set 0)</source>
        <translation>Referenzfahrt starten (Satz 0)</translation>
    </message>
    <message>
        <source>start set %1</source>
        <translation>Satz %1 starten</translation>
    </message>
    <message>
        <source>%1 answered %2: %3</source>
        <translation>%1 antwortete auf %2: %3</translation>
    </message>
    <message>
        <source>what answers is no Compax3: its info string is &quot;%1&quot;</source>
        <translation>was antwortet, ist kein Compax3: sein Info-String ist „%1“</translation>
    </message>
    <message>
        <source>, address %1</source>
        <translation>, Adresse %1</translation>
    </message>
    <message>
        <source>%1, serial number %2%3</source>
        <translation>%1, Seriennummer %2%3</translation>
    </message>
    <message>
        <source>%1 answered %2 with &quot;&gt;&quot;, not a value</source>
        <translation>%1 antwortete auf %2 mit „&gt;“, nicht mit einem Wert</translation>
    </message>
    <message>
        <source>%1 answered %2 with &quot;%3&quot;, not &quot;&gt;&quot;</source>
        <translation>%1 antwortete auf %2 mit „%3“, nicht mit „&gt;“</translation>
    </message>
    <message>
        <source>%1 answered O%2 with &quot;%3&quot;, not a number</source>
        <translation>%1 antwortete auf O%2 mit „%3“, nicht mit einer Zahl</translation>
    </message>
    <message>
        <source>the answer to &quot;%1&quot; was lost (%2); it was not sent again, because it moves the axis each time it arrives</source>
        <translation>die Antwort auf „%1“ ging verloren (%2); der Befehl wurde nicht noch einmal gesendet, weil er die Achse bei jedem Eintreffen bewegt</translation>
    </message>
    <message>
        <source>%1. Reading back failed too (%2): the axis&apos;s state is unknown; look at the machine</source>
        <translation>%1. Auch das Zurücklesen schlug fehl (%2): der Zustand der Achse ist unbekannt; sehen Sie an der Maschine nach</translation>
    </message>
    <message>
        <source>the command was taken</source>
        <translation>der Befehl wurde ausgeführt</translation>
    </message>
    <message>
        <source>the command was not taken (control word %1)</source>
        <translation>der Befehl wurde nicht ausgeführt (Steuerwort %1)</translation>
    </message>
    <message>
        <source>%1. Read back: %2; the axis is %3</source>
        <translation>%1. Zurückgelesen: %2; die Achse ist %3</translation>
    </message>
    <message>
        <source>the set must be 0 to %1, not %2</source>
        <translation>der Satz muss 0 bis %1 sein, nicht %2</translation>
    </message>
    <message>
        <source>the axis is powerless: enable it first (nothing was sent)</source>
        <translation>die Achse ist stromlos: geben Sie sie zuerst frei (nichts wurde gesendet)</translation>
    </message>
    <message>
        <source>Compax3 ASCII (RS485)</source>
        <translation>Compax3 ASCII (RS485)</translation>
    </message>
    <message>
        <source>Compax3 ASCII (RS232)</source>
        <translation>Compax3 ASCII (RS232)</translation>
    </message>
    <message>
        <source>powered, standing at %1 (last set %2)</source>
        <translation>bestromt, steht bei %1 (letzter Satz %2)</translation>
    </message>
    <message>
        <source>no Compax3 answered at any RS485 address 0..99</source>
        <translation>an keiner RS485-Adresse 0..99 antwortete ein Compax3</translation>
    </message>
    <message>
        <source>sending a break on</source>
        <translation>Senden eines Breaks auf</translation>
    </message>
    <message>
        <source>A bus scan needs the Multiuser or the Cam-BUS protocol.</source>
        <translation>Ein Bus-Scan braucht das Multiuser- oder das Cam-BUS-Protokoll.</translation>
    </message>
    <message>
        <source>a Cam-BUS block holds 1 to 255 bytes, not %1</source>
        <translation>ein Cam-BUS-Block fasst 1 bis 255 Bytes, nicht %1</translation>
    </message>
    <message>
        <source>a Cam-BUS block with LEN 0</source>
        <translation>ein Cam-BUS-Block mit LEN 0</translation>
    </message>
    <message>
        <source>a Cam-BUS block whose checksum is %1, not %2</source>
        <translation>ein Cam-BUS-Block mit Prüfsumme %1 statt %2</translation>
    </message>
    <message>
        <source>a Cam-BUS block of %1 bytes holds no CamCon frame</source>
        <translation>ein Cam-BUS-Block von %1 Bytes enthält keinen CamCon-Rahmen</translation>
    </message>
    <message>
        <source>a Cam-BUS block that does not start with ?, ! or : (0x%1)</source>
        <translation>ein Cam-BUS-Block, der nicht mit ?, ! oder : beginnt (0x%1)</translation>
    </message>
    <message>
        <source>a frame in a Cam-BUS block with checksum %1, not %2</source>
        <translation>ein Rahmen in einem Cam-BUS-Block mit Prüfsumme %1 statt %2</translation>
    </message>
    <message>
        <source>user %1 did not acknowledge the block</source>
        <translation>Teilnehmer %1 hat den Block nicht quittiert</translation>
    </message>
    <message>
        <source>an initialisation phase began before user %1 acknowledged the block</source>
        <translation>eine Initialisierungsphase begann, bevor Teilnehmer %1 den Block quittierte</translation>
    </message>
    <message>
        <source>user %1 did not answer its TO</source>
        <translation>Teilnehmer %1 hat auf sein TO nicht geantwortet</translation>
    </message>
    <message>
        <source>Cam-BUS device %1 (PC %2)</source>
        <translation>Cam-BUS Gerät %1 (PC %2)</translation>
    </message>
    <message>
        <source>check that device %1 is on the Cam-BUS (scan lists its users), the RS485 wiring and 38400 baud, and that no other user has the PC&apos;s number %2</source>
        <translation>prüfen Sie, ob Gerät %1 am Cam-BUS ist (der Scan listet die Teilnehmer), die RS485-Verdrahtung und 38400 Baud, und dass kein anderer Teilnehmer die Nummer %2 des PCs hat</translation>
    </message>
    <message>
        <source>%1 needs %2 bytes, more than a Cam-BUS block holds (255)</source>
        <translation>%1 braucht %2 Bytes, mehr als ein Cam-BUS-Block fasst (255)</translation>
    </message>
    <message>
        <source>no Cam-BUS traffic: no user passed the token in %1 s</source>
        <translation>kein Cam-BUS-Verkehr: kein Teilnehmer hat in %1 s das Token weitergegeben</translation>
    </message>
    <message>
        <source>the PC (user %1) got no turn on the Cam-BUS in %2 s</source>
        <translation>der PC (Teilnehmer %1) kam in %2 s am Cam-BUS nicht an die Reihe</translation>
    </message>
    <message>
        <source>device %1 did not take the request in %2 turns (%3); it was not executed</source>
        <translation>Gerät %1 hat die Anfrage in %2 Durchgängen nicht angenommen (%3); sie wurde nicht ausgeführt</translation>
    </message>
    <message>
        <source>the request went to device %1 but was not acknowledged (%2); it may have been executed</source>
        <translation>die Anfrage ging an Gerät %1, wurde aber nicht quittiert (%2); sie kann ausgeführt worden sein</translation>
    </message>
    <message>
        <source>a Cam-BUS: users %1 get the token; which of them are CamCons, a scan tells</source>
        <translation>ein Cam-BUS: die Teilnehmer %1 erhalten das Token; welche davon CamCons sind, zeigt ein Scan</translation>
    </message>
    <message>
        <source>no Cam-BUS token heard in %1 s</source>
        <translation>in %1 s kein Cam-BUS-Token gehört</translation>
    </message>
    <message>
        <source>no Cam-BUS traffic in %1 s on %2: no user passes the token; %3</source>
        <translation>kein Cam-BUS-Verkehr in %1 s auf %2: kein Teilnehmer gibt das Token weiter; %3</translation>
    </message>
    <message>
        <source>CamCon Cam-BUS (RS485 token bus)</source>
        <translation>CamCon Cam-BUS (RS485-Token-Bus)</translation>
    </message>
    <message>
        <source>the PC could not join the Cam-BUS: after %1 initialisation phases the master still passes user %2 no token (its answers may come too late for the bus: a USB adapter&apos;s latency timer should be 1 ms; or another user has number %2); the request was not sent</source>
        <translation>der PC konnte dem Cam-BUS nicht beitreten: nach %1 Initialisierungsphasen gibt der Master dem Teilnehmer %2 noch immer kein Token (seine Antworten kommen vielleicht zu spät für den Bus: der Latenz-Timer eines USB-Adapters sollte 1 ms sein; oder ein anderer Teilnehmer hat die Nummer %2); die Anfrage wurde nicht gesendet</translation>
    </message>
    <message>
        <source>device %1&apos;s receive queue stayed full for %2 s (it refused the request %3 times); the request was not sent</source>
        <translation>die Empfangswarteschlange von Gerät %1 blieb %2 s lang voll (es hat die Anfrage %3-mal abgewiesen); die Anfrage wurde nicht gesendet</translation>
    </message>
    <message>
        <source>not sent: dropped by STOP</source>
        <translation>nicht gesendet: durch STOPP verworfen</translation>
    </message>
    <message>
        <source>reading the number of analogue outputs</source>
        <translation>beim Lesen der Anzahl der Analogausgänge</translation>
    </message>
    <message>
        <source>The device says it has %1 analogue outputs (area 203 word 38); the manual allows 0..%2.</source>
        <translation>Das Gerät meldet %1 Analogausgänge (Bereich 203, Wort 38); das Handbuch erlaubt 0..%2.</translation>
    </message>
    <message>
        <source>line %1: %2</source>
        <translation>Zeile %1: %2</translation>
    </message>
    <message>
        <source>CamBench&apos;s built-in guess (comm/mc1/README.md), not the controller&apos;s</source>
        <translation>von CamBench eingebaute Vermutung (comm/mc1/README.md), nicht die der Steuerung</translation>
    </message>
    <message>
        <source>expected name,axis,parameter (3 fields), found %1</source>
        <translation>erwartet name,axis,parameter (3 Felder), gefunden %1</translation>
    </message>
    <message>
        <source>the name must be position, target or status, not &quot;%1&quot;</source>
        <translation>der Name muss position, target oder status sein, nicht „%1“</translation>
    </message>
    <message>
        <source>the axis must be %1 to %2, not &quot;%3&quot;</source>
        <translation>die Achse muss %1 bis %2 sein, nicht „%3“</translation>
    </message>
    <message>
        <source>the parameter must be 0 to 65535 (or 0x0000 to 0xFFFF), not &quot;%1&quot;</source>
        <translation>der Parameter muss 0 bis 65535 (oder 0x0000 bis 0xFFFF) sein, nicht „%1“</translation>
    </message>
    <message>
        <source>the %1 of axis %2 is named a second time</source>
        <translation>%1 der Achse %2 ist ein zweites Mal genannt</translation>
    </message>
    <message>
        <source>no name,axis,parameter line: the file holds no parameter</source>
        <translation>keine Zeile name,axis,parameter: die Datei enthält keinen Parameter</translation>
    </message>
    <message>
        <source> (provisional parameter numbers)</source>
        <translation> (vorläufige Parameternummern)</translation>
    </message>
    <message>
        <source>axes are numbers %1 to %2 separated by commas (1,2,5); &quot;%3&quot; is not one</source>
        <translation>Achsen sind Nummern von %1 bis %2, durch Kommas getrennt (1,2,5); „%3“ ist keine</translation>
    </message>
    <message>
        <source>no axis given: name them like 1,2,5</source>
        <translation>keine Achse angegeben: nennen Sie sie wie 1,2,5</translation>
    </message>
    <message>
        <source>as given</source>
        <translation>wie angegeben</translation>
    </message>
    <message>
        <source>none: the %1 has no axis telegrams (they need an MC200 V2)</source>
        <translation>keine: die %1 hat keine Achstelegramme (sie brauchen eine MC200 V2)</translation>
    </message>
    <message>
        <source>found with RDTABLE</source>
        <translation>mit RDTABLE gefunden</translation>
    </message>
    <message>
        <source>the parameter table (%1) names no %2 parameter for axis %3: load a table that names it</source>
        <translation>die Parametertabelle (%1) nennt keinen Parameter %2 für Achse %3: laden Sie eine Tabelle, die ihn nennt</translation>
    </message>
    <message>
        <source>the controller refused RDSTAT of parameter %1 (0x%2), the %3 of axis %4</source>
        <translation>die Steuerung hat RDSTAT von Parameter %1 (0x%2) abgelehnt, %3 der Achse %4</translation>
    </message>
    <message>
        <source>%1: that number is CamBench&apos;s guess, not the controller&apos;s; load the controller&apos;s parameter table (name,axis,parameter; --parameters FILE, or Load parameter table… on the Axes page)</source>
        <translation>%1: diese Nummer ist CamBenchs Vermutung, nicht die der Steuerung; laden Sie die Parametertabelle der Steuerung (name,axis,parameter; --parameters DATEI oder „Parametertabelle laden…“ auf der Seite Achsen)</translation>
    </message>
    <message>
        <source>%1: check the parameter table %2</source>
        <translation>%1: prüfen Sie die Parametertabelle %2</translation>
    </message>
    <message>
        <source>the controller has no axis %1: its axes are %2 (%3)</source>
        <translation>die Steuerung hat keine Achse %1: ihre Achsen sind %2 (%3)</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>no answer to &quot;%1&quot; (%2). Read back: %3</source>
        <translation>keine Antwort auf „%1“ (%2). Zurückgelesen: %3</translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>Steuerung</translation>
    </message>
    <message>
        <source>reading the axis back failed: %1</source>
        <translation>das Zurücklesen der Achse ist fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Axis %1</source>
        <translation>Achse %1</translation>
    </message>
    <message>
        <source>not acknowledged: %1; %2</source>
        <translation>nicht quittiert: %1; %2</translation>
    </message>
    <message>
        <source>the controller has no axes (%1): nothing to stop</source>
        <translation>die Steuerung hat keine Achsen (%1): nichts zu stoppen</translation>
    </message>
    <message>
        <source>axis %1 moves (provisional parameter numbers)</source>
        <translation>Achse %1 fährt (vorläufige Parameternummern)</translation>
    </message>
    <message>
        <source>axis %1 moves</source>
        <translation>Achse %1 fährt</translation>
    </message>
    <message>
        <source>none: the MC100&apos;s ASCII protocol has no axis requests</source>
        <translation>keine: das ASCII-Protokoll der MC100 hat keine Achsanfragen</translation>
    </message>
    <message>
        <source>absolute</source>
        <translation>absolut</translation>
    </message>
    <message>
        <source>relative</source>
        <translation>relativ</translation>
    </message>
    <message>
        <source>mode %1</source>
        <translation>Modus %1</translation>
    </message>
    <message>
        <source>the state could not be read back afterwards: %1</source>
        <translation>der Zustand ließ sich danach nicht zurücklesen: %1</translation>
    </message>
    <message>
        <source>the drive is powered already: nothing was sent</source>
        <translation>der Antrieb ist schon bestromt: nichts wurde gesendet</translation>
    </message>
    <message>
        <source>the drive is powered with an error pending (%1): nothing was sent, because acknowledging it drops power; stop the axis, Disable, then Enable</source>
        <translation>der Antrieb ist bestromt und hat einen Fehler (%1): nichts wurde gesendet, denn das Quittieren schaltet ihn stromlos; Achse anhalten, Abschalten, dann Freigeben</translation>
    </message>
    <message>
        <source>Compax3 drive</source>
        <translation>Compax3-Antrieb</translation>
    </message>
    <message>
        <source>Compax3 drive at address %1</source>
        <translation>Compax3-Antrieb an Adresse %1</translation>
    </message>
    <message>
        <source>STOP</source>
        <translation>STOPP</translation>
    </message>
    <message>
        <source>stopped before it moved: %1 at %2</source>
        <translation>angehalten, bevor sie fuhr: %1 um %2</translation>
    </message>
    <message>
        <source>“%1” is running on this device: motion is not queued (it would start by itself when that ends); ask again then</source>
        <translation>„%1“ läuft auf diesem Gerät: die Bewegung wird nicht eingereiht (sie würde von selbst starten, wenn das endet); fragen Sie dann erneut</translation>
    </message>
    <message numerus="yes">
        <source>; the PC was too late to answer on the bus %n time(s) during this request (the bus waits %1 ms for an answer: a USB adapter&apos;s latency timer should be 1 ms, and a computer this busy is too slow for the bus)</source>
        <translation>
            <numerusform>; der PC war während dieser Anfrage %n Mal zu spät mit seiner Antwort auf dem Bus (der Bus wartet %1 ms auf eine Antwort: der Latenz-Timer eines USB-Adapters sollte 1 ms sein, und ein so ausgelasteter Computer ist zu langsam für den Bus)</numerusform>
            <numerusform>; der PC war während dieser Anfrage %n Mal zu spät mit seiner Antwort auf dem Bus (der Bus wartet %1 ms auf eine Antwort: der Latenz-Timer eines USB-Adapters sollte 1 ms sein, und ein so ausgelasteter Computer ist zu langsam für den Bus)</numerusform>
        </translation>
    </message>
    <message>
        <source>no such axis: the controller refused its stop</source>
        <translation>keine solche Achse: die Steuerung hat ihren Stopp abgelehnt</translation>
    </message>
    <message>
        <source>could not tell whether axis %1 moves: its status was read through CamBench&apos;s guessed parameter numbers (provisional), not the controller&apos;s; load the controller&apos;s parameter table%2</source>
        <translation>ob Achse %1 fährt, ließ sich nicht sagen: ihr Zustand wurde über die von CamBench geratenen Parameternummern (vorläufig) gelesen, nicht über die der Steuerung; laden Sie die Parametertabelle der Steuerung%2</translation>
    </message>
    <message>
        <source> (besides: %1)</source>
        <translation> (außerdem: %1)</translation>
    </message>
    <message>
        <source>target</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>velocity</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>acceleration</source>
        <translation>Beschleunigung</translation>
    </message>
    <message>
        <source>deceleration</source>
        <translation>Verzögerung</translation>
    </message>
    <message>
        <source>mode %1 → %2</source>
        <translation>Modus %1 → %2</translation>
    </message>
    <message>
        <source>deceleration %1</source>
        <translation>Verzögerung %1</translation>
    </message>
    <message>
        <source>set %1 changed on the drive since it was read at %2 (%3): nothing was sent</source>
        <translation>Satz %1 wurde im Antrieb geändert, seit er um %2 gelesen wurde (%3): nichts wurde gesendet</translation>
    </message>
    <message>
        <source>%1: the axis moves (%2, as read through provisional object numbers)</source>
        <translation>%1: die Achse fährt (%2, gelesen über vorläufige Objektnummern)</translation>
    </message>
    <message>
        <source>%1: the axis is powered (as read through provisional object numbers)</source>
        <translation>%1: die Achse ist bestromt (gelesen über vorläufige Objektnummern)</translation>
    </message>
    <message>
        <source>%1 reads as %2, but through the status word 1000.3, whose number and bits are provisional (a public client&apos;s, not Parker&apos;s manual&apos;s): whether the axis stands cannot be told from it</source>
        <translation>%1 lautet %2, aber über das Statuswort 1000.3, dessen Nummer und Bits vorläufig sind (aus einem öffentlichen Client, nicht aus Parkers Handbuch): ob die Achse steht, lässt sich daraus nicht sagen</translation>
    </message>
    <message>
        <source>the drive&apos;s status could not be read (%1), so the axis was stopped by switching its power off (1100.3 = $0000), the one stop that can never power the drive; acknowledged by the drive</source>
        <translation>der Zustand des Antriebs konnte nicht gelesen werden (%1), daher wurde die Achse durch Abschalten ihrer Bestromung angehalten (1100.3 = $0000), der einzige Stopp, der den Antrieb nie bestromen kann; vom Antrieb quittiert</translation>
    </message>
    <message>
        <source>not powered: nothing to stop (nothing was sent)</source>
        <translation>nicht bestromt: nichts zu stoppen (nichts wurde gesendet)</translation>
    </message>
    <message>
        <source>Device number:</source>
        <translation>Gerätenummer:</translation>
    </message>
    <message>
        <source>the number of the CamCon to talk to on the bus</source>
        <translation>die Nummer der CamCon, mit der am Bus gesprochen wird</translation>
    </message>
    <message>
        <source>PC number:</source>
        <translation>PC-Nummer:</translation>
    </message>
    <message>
        <source>this PC&apos;s own number on the bus</source>
        <translation>die eigene Nummer dieses PCs am Bus</translation>
    </message>
    <message>
        <source>Multiuser (RS485 bus)</source>
        <translation>Multiuser (RS485-Bus)</translation>
    </message>
    <message>
        <source>Standard (point to point)</source>
        <translation>Standard (Punkt zu Punkt)</translation>
    </message>
    <message>
        <source>Table interface, 3964R n96 (9600 8N1)</source>
        <translation>Tabellenschnittstelle, 3964R n96 (9600 8N1)</translation>
    </message>
    <message>
        <source>Table interface, 3964R e38 (38400 8E1)</source>
        <translation>Tabellenschnittstelle, 3964R e38 (38400 8E1)</translation>
    </message>
    <message>
        <source>Cam-BUS (RS485 token bus)</source>
        <translation>Cam-BUS (RS485-Token-Bus)</translation>
    </message>
    <message>
        <source>this PC&apos;s own number on the Cam-BUS, usually 63; no other user of the bus (CamCon, display, another PC) may have it</source>
        <translation>die eigene Nummer dieses PCs am Cam-BUS, meist 63; kein anderer Teilnehmer des Busses (CamCon, Anzeige, anderer PC) darf sie haben</translation>
    </message>
    <message>
        <source>Controller:</source>
        <translation>Steuerung:</translation>
    </message>
    <message>
        <source>the controller variant to expect; auto (the default) probes and names what it found</source>
        <translation>die erwartete Steuerungsvariante; auto (die Vorgabe) fragt die Steuerung und nennt, was sie gefunden hat</translation>
    </message>
    <message>
        <source>RS485, 115200 8N1 unless set otherwise in the drive.</source>
        <translation>RS485, 115200 8N1, sofern im Antrieb nicht anders eingestellt.</translation>
    </message>
    <message>
        <source>RS232, 115200 8N1 with RTS/CTS unless set otherwise in the drive; a null-modem cable with RTS/CTS.</source>
        <translation>RS232, 115200 8N1 mit RTS/CTS, sofern im Antrieb nicht anders eingestellt; ein Nullmodemkabel mit RTS/CTS.</translation>
    </message>
    <message>
        <source>Drive address:</source>
        <translation>Antriebsadresse:</translation>
    </message>
    <message>
        <source>the drive&apos;s RS485 address (C3 ServoManager, &quot;RS485 settings&quot;); Scan bus lists the addresses that answer</source>
        <translation>die RS485-Adresse des Antriebs (C3 ServoManager, „RS485 Einstellungen“); „Bus durchsuchen“ listet die Adressen, die antworten</translation>
    </message>
</context>
<context>
    <name>cambench::model</name>
    <message>
        <source>a text is expected</source>
        <translation>ein Text wird erwartet</translation>
    </message>
    <message>
        <source>&quot;%1&quot; has %2 characters; at most %3 are allowed</source>
        <translation>„%1“ hat %2 Zeichen; höchstens %3 sind erlaubt</translation>
    </message>
    <message>
        <source>&quot;%1&quot; contains a character the device cannot store (only printable Latin-1 characters are allowed)</source>
        <translation>„%1“ enthält ein Zeichen, das das Gerät nicht speichern kann (nur druckbare Latin-1-Zeichen sind erlaubt)</translation>
    </message>
    <message>
        <source>%1 is not one of the allowed values %2</source>
        <translation>%1 ist keiner der erlaubten Werte %2</translation>
    </message>
    <message>
        <source>0 is not allowed; allowed are %1..-%3 and %3..%2</source>
        <translation>0 ist nicht erlaubt; erlaubt sind %1..-%3 und %3..%2</translation>
    </message>
    <message>
        <source>%1 is outside the allowed range %2%3</source>
        <translation>%1 liegt außerhalb des erlaubten Bereichs %2%3</translation>
    </message>
    <message>
        <source>%1 is not a multiple of %2 (allowed are %3 in steps of %2)</source>
        <translation>%1 ist kein Vielfaches von %2 (erlaubt sind %3 in Schritten von %2)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a whole number</source>
        <translation>„%1“ ist keine ganze Zahl</translation>
    </message>
    <message>
        <source>%1: there is no such setting.</source>
        <translation>%1: diese Einstellung gibt es nicht.</translation>
    </message>
    <message>
        <source>Could not write %1: %2. The file was not changed.</source>
        <translation>%1 konnte nicht geschrieben werden: %2. Die Datei wurde nicht verändert.</translation>
    </message>
    <message>
        <source>Could not read %1: the file does not exist.</source>
        <translation>%1 konnte nicht gelesen werden: die Datei existiert nicht.</translation>
    </message>
    <message>
        <source>Could not read %1: it is not a regular file.</source>
        <translation>%1 konnte nicht gelesen werden: es ist keine reguläre Datei.</translation>
    </message>
    <message>
        <source>Could not read %1: %2.</source>
        <translation>%1 konnte nicht gelesen werden: %2.</translation>
    </message>
    <message>
        <source>Could not read %1: it is larger than %2 bytes, so it is not a CamBench file.</source>
        <translation>%1 konnte nicht gelesen werden: sie ist größer als %2 Bytes, also keine CamBench-Datei.</translation>
    </message>
    <message>
        <source>%1 %2 is below the minimum %3</source>
        <translation>%1 %2 liegt unter dem Minimum %3</translation>
    </message>
    <message>
        <source>%1 %2 is above the maximum %3</source>
        <translation>%1 %2 liegt über dem Maximum %3</translation>
    </message>
    <message>
        <source>switch-on and switch-off point are both %1, so the cam would never switch</source>
        <translation>Einschalt- und Ausschaltpunkt sind beide %1, der Nocken würde also nie schalten</translation>
    </message>
    <message>
        <source>switch-off point %1 is below the switch-on point %2; only on a rotary axis may a cam wrap through zero</source>
        <translation>Ausschaltpunkt %1 liegt unter dem Einschaltpunkt %2; nur auf einer Rundachse darf ein Nocken über null laufen</translation>
    </message>
    <message>
        <source>the device has outputs 1..%1</source>
        <translation>das Gerät hat die Ausgänge 1..%1</translation>
    </message>
    <message>
        <source>%1 cams, but a track holds at most %2</source>
        <translation>%1 Nocken, aber eine Spur fasst höchstens %2</translation>
    </message>
    <message>
        <source>%1 overlaps cam %2 (%3)</source>
        <translation>%1 überlappt Nocken %2 (%3)</translation>
    </message>
    <message>
        <source>the device has programs 0..%1</source>
        <translation>das Gerät hat die Programme 0..%1</translation>
    </message>
    <message>
        <source>the track stored for output %1 says it is output %2</source>
        <translation>die für Ausgang %1 gespeicherte Spur gibt Ausgang %2 an</translation>
    </message>
    <message>
        <source>%1 has %2 characters; the device stores at most %3</source>
        <translation>%1 hat %2 Zeichen; das Gerät speichert höchstens %3</translation>
    </message>
    <message>
        <source>%1 contains &apos;%2&apos;, which the device cannot show (only Latin-1 characters are possible)</source>
        <translation>%1 enthält &apos;%2&apos;, das das Gerät nicht anzeigen kann (nur Latin-1-Zeichen sind möglich)</translation>
    </message>
    <message>
        <source>%1 contains the control character 0x%2</source>
        <translation>%1 enthält das Steuerzeichen 0x%2</translation>
    </message>
    <message>
        <source>Dead time of output %1: the device compensates outputs 1..%2 only.</source>
        <translation>Totzeit von Ausgang %1: das Gerät kompensiert nur die Ausgänge 1..%2.</translation>
    </message>
    <message>
        <source>Dead time of output %1: %2 is outside 0..%3 (0.1 ms steps).</source>
        <translation>Totzeit von Ausgang %1: %2 liegt außerhalb von 0..%3 (Schritte von 0,1 ms).</translation>
    </message>
    <message>
        <source>Name of output %1: the device has outputs 1..%2.</source>
        <translation>Name von Ausgang %1: das Gerät hat die Ausgänge 1..%2.</translation>
    </message>
    <message>
        <source>Name of output %1: %2.</source>
        <translation>Name von Ausgang %1: %2.</translation>
    </message>
    <message>
        <source>Name of program %1: the device has programs 0..%2.</source>
        <translation>Name von Programm %1: das Gerät hat die Programme 0..%2.</translation>
    </message>
    <message>
        <source>Name of program %1: %2.</source>
        <translation>Name von Programm %1: %2.</translation>
    </message>
    <message>
        <source>the name %1</source>
        <translation>der Name %1</translation>
    </message>
    <message>
        <source>the user number must have 1 to %1 characters</source>
        <translation>die Benutzernummer muss 1 bis %1 Zeichen haben</translation>
    </message>
    <message>
        <source>the user number may hold only printable ASCII characters</source>
        <translation>die Benutzernummer darf nur druckbare ASCII-Zeichen enthalten</translation>
    </message>
    <message>
        <source>the user number &quot;DEL&quot; is reserved: it deletes a user</source>
        <translation>die Benutzernummer „DEL“ ist reserviert: sie löscht einen Benutzer</translation>
    </message>
    <message>
        <source>%1 output access entries, but the device has %2</source>
        <translation>%1 Einträge für Ausgangszugriffe, aber das Gerät hat %2</translation>
    </message>
    <message>
        <source>%1 has the same user number as user %2; numbers must be unique.</source>
        <translation>%1 hat dieselbe Benutzernummer wie Benutzer %2; Nummern müssen eindeutig sein.</translation>
    </message>
    <message>
        <source>PLC network area 0x%1 is unknown; allowed are 0x08 (O), 0x09 (P), 0x0A (M) and 0x0B (X).</source>
        <translation>SPS-Netzwerkbereich 0x%1 ist unbekannt; erlaubt sind 0x08 (O), 0x09 (P), 0x0A (M) und 0x0B (X).</translation>
    </message>
    <message>
        <source>PLC network number %1 is outside 0..%2.</source>
        <translation>SPS-Netzwerknummer %1 liegt außerhalb von 0..%2.</translation>
    </message>
    <message>
        <source>%1 is not an integer</source>
        <translation>%1 ist keine ganze Zahl</translation>
    </message>
    <message>
        <source>%1 is not a string</source>
        <translation>%1 ist kein Text</translation>
    </message>
    <message>
        <source>%1 is not true or false</source>
        <translation>%1 ist weder true noch false</translation>
    </message>
    <message>
        <source>a JSON object is expected</source>
        <translation>ein JSON-Objekt wird erwartet</translation>
    </message>
    <message>
        <source>a JSON array is expected</source>
        <translation>ein JSON-Array wird erwartet</translation>
    </message>
    <message>
        <source>This is not a CamBench %1: it is not valid JSON (line %2: %3). The file may be truncated or damaged.</source>
        <translation>Dies ist keine CamBench-%1: sie ist kein gültiges JSON (Zeile %2: %3). Die Datei ist möglicherweise abgeschnitten oder beschädigt.</translation>
    </message>
    <message>
        <source>This is not a CamBench %1: the JSON holds no object.</source>
        <translation>Dies ist keine CamBench-%1: das JSON enthält kein Objekt.</translation>
    </message>
    <message>
        <source>This is not a CamBench %1: its &quot;format&quot; is %2, expected &quot;%3&quot;.</source>
        <translation>Dies ist keine CamBench-%1: ihr „format“ ist %2, erwartet: „%3“.</translation>
    </message>
    <message>
        <source>the format version</source>
        <translation>die Formatversion</translation>
    </message>
    <message>
        <source>This %1 was written by a newer CamBench (format version %2); this CamBench reads version %3. Open it with a newer CamBench.</source>
        <translation>Diese %1 wurde von einem neueren CamBench geschrieben (Formatversion %2); dieses CamBench liest Version %3. Öffnen Sie sie mit einem neueren CamBench.</translation>
    </message>
    <message>
        <source>%1 %2 is not a multiple of 8</source>
        <translation>%1 %2 ist kein Vielfaches von 8</translation>
    </message>
    <message>
        <source>EPROM date</source>
        <translation>EPROM-Datum</translation>
    </message>
    <message>
        <source>maximum position %1 is not above the minimum position %2</source>
        <translation>die höchste Position %1 liegt nicht über der niedrigsten Position %2</translation>
    </message>
    <message>
        <source>program number</source>
        <translation>Programmnummer</translation>
    </message>
    <message>
        <source>program name</source>
        <translation>Programmname</translation>
    </message>
    <message>
        <source>program %1 appears twice</source>
        <translation>Programm %1 kommt zweimal vor</translation>
    </message>
    <message>
        <source>output %1 appears twice</source>
        <translation>Ausgang %1 kommt zweimal vor</translation>
    </message>
    <message>
        <source>a cam is a pair [switch-on point, switch-off point], this has %1 values</source>
        <translation>ein Nocken ist ein Paar [Einschaltpunkt, Ausschaltpunkt], dieser hat %1 Werte</translation>
    </message>
    <message>
        <source>switch-on point</source>
        <translation>Einschaltpunkt</translation>
    </message>
    <message>
        <source>switch-off point</source>
        <translation>Ausschaltpunkt</translation>
    </message>
    <message>
        <source>dead time</source>
        <translation>Totzeit</translation>
    </message>
    <message>
        <source>%1 %2 appears twice</source>
        <translation>%1 %2 kommt zweimal vor</translation>
    </message>
    <message>
        <source>user name</source>
        <translation>Benutzername</translation>
    </message>
    <message>
        <source>user number</source>
        <translation>Benutzernummer</translation>
    </message>
    <message>
        <source>&quot;all outputs&quot;</source>
        <translation>„alle Ausgänge“</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is no ISO 8601 time</source>
        <translation>„%1“ ist keine Zeit nach ISO 8601</translation>
    </message>
    <message>
        <source>Program %1 appears twice.</source>
        <translation>Programm %1 kommt zweimal vor.</translation>
    </message>
    <message>
        <source>Program %1 is named &quot;%2&quot;, but the list of program names says &quot;%3&quot;.</source>
        <translation>Programm %1 heißt „%2“, aber die Liste der Programmnamen sagt „%3“.</translation>
    </message>
    <message>
        <source>PLC network %1 of area 0x%2 appears twice.</source>
        <translation>SPS-Netzwerk %1 des Bereichs 0x%2 kommt zweimal vor.</translation>
    </message>
    <message>
        <source>Block %1 (entry %2 of the list)</source>
        <translation>Block %1 (Eintrag %2 der Liste)</translation>
    </message>
    <message>
        <source>block number</source>
        <translation>Blocknummer</translation>
    </message>
    <message>
        <source>block data</source>
        <translation>Blockdaten</translation>
    </message>
    <message>
        <source>block data is not an even number of hex digits</source>
        <translation>die Blockdaten sind keine gerade Zahl von Hex-Ziffern</translation>
    </message>
    <message>
        <source>The image holds no blocks.</source>
        <translation>Das Abbild enthält keine Blöcke.</translation>
    </message>
    <message>
        <source>The image does not start with block 0000 (the basic parameters) but with block %1.</source>
        <translation>Das Abbild beginnt nicht mit Block 0000 (den Grundparametern), sondern mit Block %1.</translation>
    </message>
    <message>
        <source>Block 0000 has %1 bytes; the basic-parameter block has %2.</source>
        <translation>Block 0000 hat %1 Bytes; der Grundparameterblock hat %2.</translation>
    </message>
    <message>
        <source>%1 does not follow block %2: block numbers must ascend.</source>
        <translation>%1 folgt nicht auf Block %2: Blocknummern müssen aufsteigen.</translation>
    </message>
    <message>
        <source>%1: FFFF marks the end of the EEPROM and is no block.</source>
        <translation>%1: FFFF markiert das Ende des EEPROMs und ist kein Block.</translation>
    </message>
    <message>
        <source>%1: its first byte 0x%2 gives no length (upper 4 bits are 0).</source>
        <translation>%1: sein erstes Byte 0x%2 gibt keine Länge an (die oberen 4 Bits sind 0).</translation>
    </message>
    <message>
        <source>%1 has %2 bytes, but its first byte 0x%3 says %4.</source>
        <translation>%1 hat %2 Bytes, aber sein erstes Byte 0x%3 sagt %4.</translation>
    </message>
    <message>
        <source>%1: image %2, device %3.</source>
        <translation>%1: Abbild %2, Gerät %3.</translation>
    </message>
    <message>
        <source>The file was changed or damaged: its SHA-256 checksum does not match its content. Do not restore it; take a new backup.</source>
        <translation>Die Datei wurde verändert oder beschädigt: ihre SHA-256-Prüfsumme passt nicht zum Inhalt. Stellen Sie sie nicht wieder her; erstellen Sie eine neue Sicherung.</translation>
    </message>
    <message>
        <source>time taken</source>
        <translation>Zeitpunkt der Sicherung</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not an ISO 8601 date and time</source>
        <translation>„%1“ ist kein Datum mit Uhrzeit nach ISO 8601</translation>
    </message>
    <message>
        <source>%1 was not saved: %2</source>
        <translation>%1 wurde nicht gespeichert: %2</translation>
    </message>
    <message>
        <source>Line %1: %2. Nothing was imported.</source>
        <translation>Zeile %1: %2. Nichts wurde importiert.</translation>
    </message>
    <message>
        <source>a quoted field has no closing quote</source>
        <translation>einem Feld in Anführungszeichen fehlt das schließende Anführungszeichen</translation>
    </message>
    <message>
        <source>there is text after a closing quote</source>
        <translation>nach einem schließenden Anführungszeichen steht Text</translation>
    </message>
    <message>
        <source>The file is not UTF-8 text. Nothing was imported.</source>
        <translation>Die Datei ist kein UTF-8-Text. Nichts wurde importiert.</translation>
    </message>
    <message>
        <source>the header must be &quot;%1&quot;, found &quot;%2&quot;</source>
        <translation>die Kopfzeile muss „%1“ sein, gefunden: „%2“</translation>
    </message>
    <message>
        <source>%1 fields, expected %2 (%3)</source>
        <translation>%1 Felder, erwartet: %2 (%3)</translation>
    </message>
    <message>
        <source>%1 &quot;%2&quot; is not a whole number</source>
        <translation>%1 „%2“ ist keine ganze Zahl</translation>
    </message>
    <message>
        <source>output %1 has a cam %2 already (line %3)</source>
        <translation>Ausgang %1 hat schon einen Nocken %2 (Zeile %3)</translation>
    </message>
    <message>
        <source>cam %1 of output %2, but cam %3 is missing; number the cams of an output 1, 2, 3, ...</source>
        <translation>Nocken %1 von Ausgang %2, aber Nocken %3 fehlt; nummerieren Sie die Nocken eines Ausgangs 1, 2, 3, ...</translation>
    </message>
    <message>
        <source>output %1 has a dead time already (line %2)</source>
        <translation>Ausgang %1 hat schon eine Totzeit (Zeile %2)</translation>
    </message>
    <message>
        <source>kind &quot;%1&quot; is neither &quot;output&quot; nor &quot;program&quot;</source>
        <translation>Art „%1“ ist weder „output“ noch „program“</translation>
    </message>
    <message>
        <source>%1 %2 has a name already (line %3)</source>
        <translation>%1 %2 hat schon einen Namen (Zeile %3)</translation>
    </message>
    <message>
        <source>there is no such setting</source>
        <translation>diese Einstellung gibt es nicht</translation>
    </message>
    <message>
        <source>the value is not a text</source>
        <translation>der Wert ist kein Text</translation>
    </message>
    <message>
        <source>the value</source>
        <translation>der Wert</translation>
    </message>
    <message>
        <source>the area &quot;%1&quot; is none of O, P, M, X</source>
        <translation>der Bereich „%1“ ist keiner von O, P, M, X</translation>
    </message>
    <message>
        <source>&quot;area&quot; is missing</source>
        <translation>„area“ fehlt</translation>
    </message>
    <message>
        <source>network number</source>
        <translation>Netzwerknummer</translation>
    </message>
    <message>
        <source>reset field</source>
        <translation>Rücksetzfeld</translation>
    </message>
    <message>
        <source>%1 symbols, expected %2 (%3 paths of %4)</source>
        <translation>%1 Symbole, erwartet: %2 (%3 Strompfade zu %4)</translation>
    </message>
    <message>
        <source>network %1%2 appears twice</source>
        <translation>Netzwerk %1%2 kommt zweimal vor</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is no ISO time</source>
        <translation>„%1“ ist keine ISO-Zeit</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is neither &quot;saved&quot; nor &quot;failed&quot;</source>
        <translation>„%1“ ist weder „saved“ noch „failed“</translation>
    </message>
    <message>
        <source>device %1 appears twice</source>
        <translation>Gerät %1 kommt zweimal vor</translation>
    </message>
    <message>
        <source> (0 = none)</source>
        <translation> (0 = keiner)</translation>
    </message>
    <message>
        <source>program %1</source>
        <translation>Programm %1</translation>
    </message>
    <message>
        <source>, output %1</source>
        <translation>, Ausgang %1</translation>
    </message>
    <message>
        <source>, cam %1</source>
        <translation>, Nocken %1</translation>
    </message>
    <message>
        <source>User %1 (%2)</source>
        <translation>Benutzer %1 (%2)</translation>
    </message>
    <message>
        <source>%1 %2 is outside %3..%4</source>
        <translation>%1 %2 liegt außerhalb von %3..%4</translation>
    </message>
    <message>
        <source>%1 is empty.</source>
        <translation>%1 ist leer.</translation>
    </message>
    <message>
        <source>area (O, P, M or X)</source>
        <translation>Bereich (O, P, M oder X)</translation>
    </message>
    <message>
        <source>PLC network %1%2</source>
        <translation>SPS-Netzwerk %1%2</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Abgebrochen.</translation>
    </message>
    <message>
        <source>Output %1 has no dead-time compensation on this device (outputs 1..%2 have one).</source>
        <translation>Ausgang %1 hat auf diesem Gerät keine Totzeitkompensation (die Ausgänge 1..%2 haben eine).</translation>
    </message>
    <message>
        <source>Output %1: dead-time mode %2 is unknown (0 normal, 1 on/off, 2 path-time).</source>
        <translation>Ausgang %1: Totzeit-Modus %2 ist unbekannt (0 normal, 1 ein/aus, 2 Weg-Zeit).</translation>
    </message>
    <message>
        <source>Output %1: the dead time %2 is outside 0..%3 (0.1 ms), the device&apos;s range.</source>
        <translation>Ausgang %1: die Totzeit %2 liegt außerhalb von 0..%3 (0,1 ms), dem Bereich des Geräts.</translation>
    </message>
    <message>
        <source>Output %1: the switch-on dead time %2 is outside 0..%3 (0.1 ms), the device&apos;s range.</source>
        <translation>Ausgang %1: die Einschalttotzeit %2 liegt außerhalb von 0..%3 (0,1 ms), dem Bereich des Geräts.</translation>
    </message>
    <message>
        <source>Output %1: the switching time %2 is outside 0..%3 (0.1 ms), the device&apos;s range.</source>
        <translation>Ausgang %1: die Schaltzeit %2 liegt außerhalb von 0..%3 (0,1 ms), dem Bereich des Geräts.</translation>
    </message>
    <message>
        <source>Output %1: the switch-off dead time %2 is outside 0..%3 (0.1 ms), the device&apos;s range.</source>
        <translation>Ausgang %1: die Ausschalttotzeit %2 liegt außerhalb von 0..%3 (0,1 ms), dem Bereich des Geräts.</translation>
    </message>
    <message>
        <source>Analogue output %1 does not exist (1..%2).</source>
        <translation>Analogausgang %1 existiert nicht (1..%2).</translation>
    </message>
    <message>
        <source>Analogue output %1 has %2 base points; at most %3 fit.</source>
        <translation>Analogausgang %1 hat %2 Stützpunkte; höchstens %3 passen.</translation>
    </message>
    <message>
        <source>Analogue output %1, base point %2</source>
        <translation>Analogausgang %1, Stützpunkt %2</translation>
    </message>
    <message>
        <source>%1: position %2 is outside %3..%4.</source>
        <translation>%1: Position %2 liegt außerhalb von %3..%4.</translation>
    </message>
    <message>
        <source>%1: position %2 does not come after the previous point&apos;s %3; order the points by position.</source>
        <translation>%1: Position %2 folgt nicht auf %3 des vorigen Punkts; ordnen Sie die Punkte nach Position.</translation>
    </message>
    <message>
        <source>%1: value %2 is outside %3..%4.</source>
        <translation>%1: Wert %2 liegt außerhalb von %3..%4.</translation>
    </message>
    <message>
        <source>Programming program %1 does not exist (programs 0..%2).</source>
        <translation>Programmierprogramm %1 existiert nicht (Programme 0..%2).</translation>
    </message>
    <message>
        <source>Programming program select mode %1 is unknown (0 slow, 1 direct, 2 at the actual value).</source>
        <translation>Anwahlmodus %1 des Programmierprogramms ist unbekannt (0 langsam, 1 direkt, 2 am Istwert).</translation>
    </message>
    <message>
        <source>Programming program switch value %1 is outside %2..%3.</source>
        <translation>Umschaltwert %1 des Programmierprogramms liegt außerhalb von %2..%3.</translation>
    </message>
    <message>
        <source>cannot make it readable by its owner only (%1)</source>
        <translation>kann sie nicht nur für ihren Eigentümer lesbar machen (%1)</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is missing</source>
        <translation>„%1“ fehlt</translation>
    </message>
    <message>
        <source>missing</source>
        <translation>nicht vorhanden</translation>
    </message>
    <message>
        <source>output</source>
        <translation>Ausgang</translation>
    </message>
    <message>
        <source>name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>rights</source>
        <translation>Rechte</translation>
    </message>
    <message>
        <source>time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>tool</source>
        <translation>Erstellerprogramm</translation>
    </message>
    <message>
        <source>value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>symbol</source>
        <translation>Symbol</translation>
    </message>
    <message>
        <source>dead-time mode</source>
        <translation>Totzeit-Modus</translation>
    </message>
    <message>
        <source>unknown mode &quot;%1&quot;; use normal, on/off or path-time</source>
        <translation>unbekannter Modus „%1“; verwenden Sie normal, on/off oder path-time</translation>
    </message>
    <message>
        <source>switch-on dead time</source>
        <translation>Einschalttotzeit</translation>
    </message>
    <message>
        <source>switch-off dead time</source>
        <translation>Ausschalttotzeit</translation>
    </message>
    <message>
        <source>Output %1: the dead time %2 and the dead time of its dead-time mode %3 (0.1 ms) differ, but the device holds one value for both.</source>
        <translation>Ausgang %1: die Totzeit %2 und die Totzeit seines Totzeit-Modus %3 (0,1 ms) unterscheiden sich, das Gerät hält aber einen Wert für beide.</translation>
    </message>
    <message>
        <source>EEPROM lock</source>
        <translation>EEPROM-Sperre</translation>
    </message>
    <message>
        <source>analogue output %1 has base points and a row without any; use &quot;%1,,&quot; only for an output without points</source>
        <translation>Analogausgang %1 hat Stützpunkte und eine Zeile ohne; &quot;%1,,&quot; nur für einen Ausgang ohne Punkte verwenden</translation>
    </message>
    <message>
        <source>analogue output</source>
        <translation>Analogausgang</translation>
    </message>
    <message>
        <source>a base point is [position, value], two numbers</source>
        <translation>ein Stützpunkt ist [Position, Wert], zwei Zahlen</translation>
    </message>
    <message>
        <source>position</source>
        <translation>Position</translation>
    </message>
    <message>
        <source>analogue output %1 appears twice</source>
        <translation>Analogausgang %1 kommt zweimal vor</translation>
    </message>
    <message>
        <source>programming program</source>
        <translation>Programmierprogramm</translation>
    </message>
    <message>
        <source>select mode</source>
        <translation>Umschaltart</translation>
    </message>
    <message>
        <source>unknown select mode &quot;%1&quot;; use slow, direct or at-value</source>
        <translation>unbekannte Umschaltart &quot;%1&quot;; slow, direct oder at-value verwenden</translation>
    </message>
    <message>
        <source>switch value</source>
        <translation>Umschalt-Istwert</translation>
    </message>
    <message>
        <source>This %1 is for devices of the family &quot;%2&quot;, not &quot;%3&quot;: nothing was loaded. Open it where a device of that family is connected.</source>
        <translation>Diese Datei (%1) ist für Geräte der Familie &quot;%2&quot;, nicht &quot;%3&quot;: nichts wurde geladen. Öffnen Sie sie, wo ein Gerät dieser Familie angeschlossen ist.</translation>
    </message>
    <message>
        <source>minimum pulse</source>
        <translation>Mindestimpuls</translation>
    </message>
    <message>
        <source>not an even number of hexadecimal digits</source>
        <translation>keine gerade Anzahl Hexadezimalziffern</translation>
    </message>
    <message>
        <source>not a pair [number, value]</source>
        <translation>kein Paar [Nummer, Wert]</translation>
    </message>
    <message>
        <source>variable number</source>
        <translation>Variablennummer</translation>
    </message>
    <message>
        <source>value (%1 bits)</source>
        <translation>Wert (%1 Bit)</translation>
    </message>
    <message>
        <source>V%1 a second time</source>
        <translation>V%1 ein zweites Mal</translation>
    </message>
    <message>
        <source>address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <source>data</source>
        <translation>Daten</translation>
    </message>
    <message>
        <source>%1 bytes from 0x%2 do not fit memory 0x0000–0xFFFF</source>
        <translation>%1 Bytes ab 0x%2 passen nicht in den Speicher 0x0000–0xFFFF</translation>
    </message>
    <message>
        <source>overlaps the range before it or is out of order</source>
        <translation>überlappt den Bereich davor oder steht nicht in Reihenfolge</translation>
    </message>
    <message>
        <source>controller variant</source>
        <translation>Steuerungsvariante</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is none of mc100v1, mc100v2, mc200v1, mc200v2</source>
        <translation>&quot;%1&quot; ist keine von mc100v1, mc100v2, mc200v1, mc200v2</translation>
    </message>
    <message>
        <source>flag page</source>
        <translation>Merkerseite</translation>
    </message>
    <message>
        <source>flags</source>
        <translation>Merker</translation>
    </message>
    <message>
        <source>%1 bytes, not the page&apos;s %2</source>
        <translation>%1 Bytes, nicht die %2 der Seite</translation>
    </message>
    <message>
        <source>sha256: the checksum is missing.</source>
        <translation>sha256: die Prüfsumme fehlt.</translation>
    </message>
    <message>
        <source>point</source>
        <translation>Punkt</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not %2</source>
        <translation>&quot;%1&quot; ist nicht %2</translation>
    </message>
    <message>
        <source>%1 a second time</source>
        <translation>%1 ein zweites Mal</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is none of auto, mc100v1, mc100v2, mc200v1, mc200v2</source>
        <translation>&quot;%1&quot; ist keine von auto, mc100v1, mc100v2, mc200v1, mc200v2</translation>
    </message>
    <message>
        <source>a variable such as V12</source>
        <translation>eine Variable wie V12</translation>
    </message>
    <message>
        <source>a flag, input or output such as M2327</source>
        <translation>ein Merker, Eingang oder Ausgang wie M2327</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a Compax3 object; write index.subindex, e.g. 680.5 (also o680.5, O 680,5, $ for hexadecimal; index up to 65535, subindex up to 255)</source>
        <translation>„%1“ ist kein Compax3-Objekt; schreiben Sie Index.Subindex, z. B. 680.5 (auch o680.5, O 680,5, $ für hexadezimal; Index bis 65535, Subindex bis 255)</translation>
    </message>
    <message>
        <source>%1 to %2</source>
        <translation>%1 bis %2</translation>
    </message>
    <message>
        <source>at least %1</source>
        <translation>mindestens %1</translation>
    </message>
    <message>
        <source>at most %1</source>
        <translation>höchstens %1</translation>
    </message>
    <message>
        <source>a text for the drive cannot hold &quot; or a line break</source>
        <translation>ein Text für den Antrieb kann kein &quot; und keinen Zeilenumbruch enthalten</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: write the number with a decimal point (%2); the drive takes a comma for a syntax error</source>
        <translation>„%1“: schreiben Sie die Zahl mit Dezimalpunkt (%2); der Antrieb hält ein Komma für einen Syntaxfehler</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a number (decimal, or $ and hexadecimal digits)</source>
        <translation>„%1“ ist keine Zahl (dezimal, oder $ und Hex-Ziffern)</translation>
    </message>
    <message>
        <source>%1 is outside the object&apos;s range (%2)</source>
        <translation>%1 liegt außerhalb des Bereichs des Objekts (%2)</translation>
    </message>
    <message>
        <source>no value given</source>
        <translation>kein Wert angegeben</translation>
    </message>
    <message>
        <source>not a number</source>
        <translation>keine Zahl</translation>
    </message>
    <message>
        <source>object</source>
        <translation>Objekt</translation>
    </message>
    <message>
        <source>type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <source>access</source>
        <translation>Zugriff</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not integer, real or text</source>
        <translation>„%1“ ist weder integer, real noch text</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not ro, rw, wo or cmd</source>
        <translation>„%1“ ist weder ro, rw, wo noch cmd</translation>
    </message>
    <message>
        <source>min is above max</source>
        <translation>min liegt über max</translation>
    </message>
    <message>
        <source>Other</source>
        <translation>Sonstige</translation>
    </message>
    <message>
        <source>object %1 a second time</source>
        <translation>Objekt %1 ein zweites Mal</translation>
    </message>
    <message>
        <source>line %1: %2.</source>
        <translation>Zeile %1: %2.</translation>
    </message>
    <message>
        <source>built in</source>
        <translation>eingebaut</translation>
    </message>
    <message>
        <source>%1 (%2) is read-only</source>
        <translation>%1 (%2) ist nur lesbar</translation>
    </message>
    <message>
        <source>info string</source>
        <translation>Info-String</translation>
    </message>
    <message>
        <source>not an object of name, group and help</source>
        <translation>kein Objekt aus name, group und help</translation>
    </message>
    <message>
        <source>%1 is a control word: a file never starts or stops the axis (use the Motion page or c3 enable/jog/move/stop)</source>
        <translation>%1 ist ein Steuerwort: eine Datei startet oder stoppt die Achse nie (Seite Bewegung oder c3 enable/jog/move/stop benutzen)</translation>
    </message>
    <message>
        <source>%1 is a function, not a value: a file never triggers it</source>
        <translation>%1 ist eine Funktion, kein Wert: eine Datei löst sie nie aus</translation>
    </message>
    <message>
        <source>language of the Compax3 refusals: en</source>
        <translation>de</translation>
    </message>
    <message>
        <source>object %1 both with a value and absent</source>
        <translation>Objekt %1 zugleich mit Wert und als fehlend</translation>
    </message>
    <message>
        <source>%1 added</source>
        <translation>%1 hinzugefügt</translation>
    </message>
    <message>
        <source>%1 removed</source>
        <translation>%1 entfernt</translation>
    </message>
    <message>
        <source>cam</source>
        <translation>Nocken</translation>
    </message>
    <message>
        <source>program %1, output %2</source>
        <translation>Programm %1, Ausgang %2</translation>
    </message>
    <message>
        <source>%1 flags, not the page&apos;s %2</source>
        <translation>%1 Merker, nicht die %2 der Seite</translation>
    </message>
    <message>
        <source>not [&quot;%1&quot;, 0 or 1]</source>
        <translation>nicht [&quot;%1&quot;, 0 oder 1]</translation>
    </message>
    <message>
        <source>flag</source>
        <translation>Merker</translation>
    </message>
    <message>
        <source>not [&quot;object&quot;, &quot;value&quot;, &quot;name&quot;]</source>
        <translation>nicht [&quot;object&quot;, &quot;value&quot;, &quot;name&quot;]</translation>
    </message>
    <message>
        <source>not recorded</source>
        <translation>nicht aufgezeichnet</translation>
    </message>
    <message>
        <source>%1 is not an object of names and texts ({&quot;serial&quot;: &quot;...&quot;}).</source>
        <translation>%1 ist kein Objekt aus Namen und Texten ({&quot;serial&quot;: &quot;...&quot;}).</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; must be a text, as CamBench wrote it.</source>
        <translation>%1: &quot;%2&quot; muss ein Text sein, wie CamBench ihn geschrieben hat.</translation>
    </message>
    <message>
        <source>which device this is cannot be told: no identity was recorded for it; found %1</source>
        <translation>welches Gerät dies ist, lässt sich nicht sagen: für es wurde keine Identität aufgezeichnet; gefunden %1</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>another device answers: expected %1, found %2</source>
        <translation>ein anderes Gerät antwortet: erwartet %1, gefunden %2</translation>
    </message>
    <message>
        <source>%1 records no identity of the device it was taken from (a backup older than that record), so CamBench cannot tell whether the device answering (%2) is that device. Nothing was written. If it is, or if it replaces that device, confirm it (on the command line: --replacement).</source>
        <translation>%1 zeichnet keine Identität des Geräts auf, von dem es stammt (eine Sicherung, älter als diese Aufzeichnung), daher kann CamBench nicht sagen, ob das antwortende Gerät (%2) dieses Gerät ist. Nichts wurde geschrieben. Wenn es das ist oder es dieses Gerät ersetzt, bestätigen Sie es (auf der Kommandozeile: --replacement).</translation>
    </message>
    <message>
        <source>%1 was taken from another device: %2 (the backup&apos;s device: %3; the device answering: %4). Nothing was written. Only if this device replaces that one, confirm it (on the command line: --replacement).</source>
        <translation>%1 stammt von einem anderen Gerät: %2 (das Gerät der Sicherung: %3; das antwortende Gerät: %4). Nichts wurde geschrieben. Nur wenn dieses Gerät jenes ersetzt, bestätigen Sie es (auf der Kommandozeile: --replacement).</translation>
    </message>
    <message>
        <source>The git program could not be started (%1); the machine archive is a git repository: install git (Debian: apt install git).</source>
        <translation>Das Programm git konnte nicht gestartet werden (%1); das Maschinenarchiv ist ein git-Repository: installieren Sie git (Debian: apt install git).</translation>
    </message>
    <message>
        <source>%1 in %2 did not finish within %3 s (a lock held by another git?); nothing more was done.</source>
        <translation>%1 in %2 wurde nicht innerhalb von %3 s fertig (eine Sperre eines anderen git?); nichts weiter wurde getan.</translation>
    </message>
    <message>
        <source>%1 in %2 failed (exit %3): %4</source>
        <translation>%1 in %2 fehlgeschlagen (Exit %3): %4</translation>
    </message>
    <message>
        <source>%1 is no machine archive: there is no such folder (`machine backup M.json --archive %1` makes one).</source>
        <translation>%1 ist kein Maschinenarchiv: diesen Ordner gibt es nicht (`machine backup M.json --archive %1` legt einen an).</translation>
    </message>
    <message>
        <source>%1 is no machine archive: it is not the top folder of a git repository (`machine backup M.json --archive DIR` makes one).</source>
        <translation>%1 ist kein Maschinenarchiv: es ist nicht der oberste Ordner eines git-Repositorys (`machine backup M.json --archive DIR` legt einen an).</translation>
    </message>
    <message>
        <source>Cannot make the archive folder %1; check the path and its rights.</source>
        <translation>Der Archivordner %1 kann nicht angelegt werden; prüfen Sie den Pfad und seine Rechte.</translation>
    </message>
    <message>
        <source>%1 holds files but is no git repository: it is not made an archive (name an empty or new folder).</source>
        <translation>%1 enthält Dateien, ist aber kein git-Repository: es wird nicht zum Archiv gemacht (nennen Sie einen leeren oder neuen Ordner).</translation>
    </message>
    <message>
        <source>%1 names no version of %2.</source>
        <translation>%1 nennt keine Version von %2.</translation>
    </message>
    <message>
        <source>%1 holds no version yet (`machine backup M.json --archive %1 -m WHY` stores the first).</source>
        <translation>%1 enthält noch keine Version (`machine backup M.json --archive %1 -m WHY` speichert die erste).</translation>
    </message>
    <message>
        <source>%1 names no version of %2 (`machine history %2` lists them: a commit id, a prefix of one or a tag).</source>
        <translation>%1 nennt keine Version von %2 (`machine history %2` listet sie auf: eine Commit-ID, ein Präfix davon oder ein Tag).</translation>
    </message>
    <message>
        <source>No version of %1 is released (`machine release %1 VERSION` marks the one that should be on the machine).</source>
        <translation>Keine Version von %1 ist freigegeben (`machine release %1 VERSION` markiert die, die auf der Maschine sein soll).</translation>
    </message>
    <message>
        <source>Cannot make the folder for %1.</source>
        <translation>Der Ordner für %1 kann nicht angelegt werden.</translation>
    </message>
    <message>
        <source>Cannot read %1: %2; no version was stored.</source>
        <translation>%1 kann nicht gelesen werden: %2; es wurde keine Version gespeichert.</translation>
    </message>
</context>
<context>
    <name>cambench::plcsymbol</name>
    <message>
        <source>&quot;%1&quot; is not taken: CamBench knows the operands O, P, M and X only (P are the cam controller&apos;s inputs, e.g. P5). Enter one of them with a number, or the symbol word as 4 hex digits.</source>
        <translation>„%1“ wird nicht übernommen: CamBench kennt nur die Operanden O, P, M und X (P sind die Eingänge des Nockenschaltwerks, z. B. P5). Geben Sie einen davon mit einer Nummer ein oder das Symbolwort als 4 Hex-Ziffern.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not taken: the number must be 1 … 256.</source>
        <translation>„%1“ wird nicht übernommen: die Nummer muss 1 … 256 sein.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not taken: enter an operand such as M11 or P5, 4 hex digits (0A0A), or nothing to clear the symbol.</source>
        <translation>„%1“ wird nicht übernommen: geben Sie einen Operanden wie M11 oder P5 ein, 4 Hex-Ziffern (0A0A) oder nichts, um das Symbol zu leeren.</translation>
    </message>
</context>
<context>
    <name>cambench::usecases</name>
    <message>
        <source>, the device keeps %1</source>
        <translation>, das Gerät behält %1</translation>
    </message>
    <message>
        <source>, the device NOW HOLDS %1</source>
        <translation>, das Gerät ENTHÄLT JETZT %1</translation>
    </message>
    <message>
        <source>, what the device holds now could not be read</source>
        <translation>, was das Gerät jetzt enthält, ließ sich nicht lesen</translation>
    </message>
    <message>
        <source>written</source>
        <translation>geschrieben</translation>
    </message>
    <message>
        <source>unchanged</source>
        <translation>unverändert</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>fehlgeschlagen</translation>
    </message>
    <message>
        <source>changed though the write failed</source>
        <translation>geändert, obwohl das Schreiben fehlschlug</translation>
    </message>
    <message>
        <source>failed, state unknown</source>
        <translation>fehlgeschlagen, Zustand unbekannt</translation>
    </message>
    <message>
        <source>not sent</source>
        <translation>nicht gesendet</translation>
    </message>
    <message>
        <source>%1 written</source>
        <translation>%1 geschrieben</translation>
    </message>
    <message>
        <source>%1 unchanged</source>
        <translation>%1 unverändert</translation>
    </message>
    <message>
        <source>%1 failed (the device keeps its old values)</source>
        <translation>%1 fehlgeschlagen (das Gerät behält seine alten Werte)</translation>
    </message>
    <message>
        <source>%1 CHANGED THOUGH THE WRITE FAILED</source>
        <translation>%1 GEÄNDERT, OBWOHL DAS SCHREIBEN FEHLSCHLUG</translation>
    </message>
    <message>
        <source>%1 failed with the device&apos;s state unknown</source>
        <translation>%1 fehlgeschlagen, Zustand des Geräts unbekannt</translation>
    </message>
    <message>
        <source>%1 not sent</source>
        <translation>%1 nicht gesendet</translation>
    </message>
    <message>
        <source>%1 items: %2</source>
        <translation>%1 Elemente: %2</translation>
    </message>
    <message>
        <source>no cams</source>
        <translation>keine Nocken</translation>
    </message>
    <message>
        <source>no name</source>
        <translation>kein Name</translation>
    </message>
    <message>
        <source>no values</source>
        <translation>keine Werte</translation>
    </message>
    <message>
        <source>no such user</source>
        <translation>kein solcher Benutzer</translation>
    </message>
    <message>
        <source>user %1 with rights 0x%2 and %3</source>
        <translation>Benutzer %1 mit Rechten 0x%2 und %3</translation>
    </message>
    <message>
        <source>all outputs</source>
        <translation>alle Ausgänge</translation>
    </message>
    <message>
        <source>%1 outputs</source>
        <translation>%1 Ausgänge</translation>
    </message>
    <message>
        <source>value %1, reset 0x%2, %3 symbols set</source>
        <translation>Wert %1, Rücksetzen 0x%2, %3 Symbole gesetzt</translation>
    </message>
    <message>
        <source>program %1, output %2</source>
        <translation>Programm %1, Ausgang %2</translation>
    </message>
    <message>
        <source>dead time of output %1</source>
        <translation>Totzeit von Ausgang %1</translation>
    </message>
    <message>
        <source>name of output %1</source>
        <translation>Name von Ausgang %1</translation>
    </message>
    <message>
        <source>name of program %1</source>
        <translation>Name von Programm %1</translation>
    </message>
    <message>
        <source>settings %1 (%2)</source>
        <translation>Einstellungen %1 (%2)</translation>
    </message>
    <message>
        <source>user %1</source>
        <translation>Benutzer %1</translation>
    </message>
    <message>
        <source>PLC network %1%2</source>
        <translation>SPS-Netzwerk %1%2</translation>
    </message>
    <message>
        <source>Setting %1: there is no such setting.</source>
        <translation>Einstellung %1: diese Einstellung gibt es nicht.</translation>
    </message>
    <message>
        <source>Setting %1 is read-only: the device decides it (wanted %2%3).</source>
        <translation>Einstellung %1 ist nur lesbar: das Gerät bestimmt sie (gewünscht %2%3).</translation>
    </message>
    <message>
        <source>, the device has %1</source>
        <translation>, das Gerät hat %1</translation>
    </message>
    <message>
        <source>Name of program %1: the device has programs 0..%2.</source>
        <translation>Name von Programm %1: das Gerät hat die Programme 0..%2.</translation>
    </message>
    <message>
        <source>Name of program %1: %2.</source>
        <translation>Name von Programm %1: %2.</translation>
    </message>
    <message>
        <source>Program %1: the device has programs 0..%2.</source>
        <translation>Programm %1: das Gerät hat die Programme 0..%2.</translation>
    </message>
    <message>
        <source>%1: the plan holds this track twice.</source>
        <translation>%1: der Plan enthält diese Spur zweimal.</translation>
    </message>
    <message>
        <source>%1: the device has outputs 1..%2.</source>
        <translation>%1: das Gerät hat die Ausgänge 1..%2.</translation>
    </message>
    <message>
        <source>Dead time of output %1: the device compensates outputs 1..%2 only.</source>
        <translation>Totzeit von Ausgang %1: das Gerät kompensiert nur die Ausgänge 1..%2.</translation>
    </message>
    <message>
        <source>Dead time of output %1: %2 is outside 0..%3 (0.1 ms steps).</source>
        <translation>Totzeit von Ausgang %1: %2 liegt außerhalb von 0..%3 (Schritte von 0,1 ms).</translation>
    </message>
    <message>
        <source>Name of output %1: the device has outputs 1..%2.</source>
        <translation>Name von Ausgang %1: das Gerät hat die Ausgänge 1..%2.</translation>
    </message>
    <message>
        <source>Name of output %1: %2.</source>
        <translation>Name von Ausgang %1: %2.</translation>
    </message>
    <message>
        <source>%1: the device has no user with the number given for it; read the users again.</source>
        <translation>%1: das Gerät hat keinen Benutzer mit der dafür angegebenen Nummer; lesen Sie die Benutzer erneut.</translation>
    </message>
    <message>
        <source>%1 has no number and the device has no user of that name whose number it could keep; enter a number.</source>
        <translation>%1 hat keine Nummer, und das Gerät hat keinen Benutzer dieses Namens, dessen Nummer er behalten könnte; geben Sie eine Nummer ein.</translation>
    </message>
    <message>
        <source>%1 would have the same user number as %2; numbers must be unique.</source>
        <translation>%1 hätte dieselbe Benutzernummer wie %2; Nummern müssen eindeutig sein.</translation>
    </message>
    <message>
        <source>%1: the device has %2 networks in area %3 (%3%4); change the PLC counts in the settings first.</source>
        <translation>%1: das Gerät hat %2 Netzwerke im Bereich %3 (%3%4); ändern Sie zuerst die SPS-Anzahlen in den Einstellungen.</translation>
    </message>
    <message>
        <source>outputs %1 do not exist on the device (it has 1..%2)</source>
        <translation>die Ausgänge %1 gibt es im Gerät nicht (es hat 1..%2)</translation>
    </message>
    <message>
        <source>programs %1 do not exist on the device (it has 0..%2)</source>
        <translation>die Programme %1 gibt es im Gerät nicht (es hat 0..%2)</translation>
    </message>
    <message>
        <source>%1 cam points lie outside the device&apos;s range %2..%3</source>
        <translation>%1 Nockenpunkte liegen außerhalb des Bereichs %2..%3 des Geräts</translation>
    </message>
    <message>
        <source>the plan holds invalid values</source>
        <translation>der Plan enthält ungültige Werte</translation>
    </message>
    <message>
        <source>The write was refused before anything was sent: %1 (%2):</source>
        <translation>Das Schreiben wurde abgelehnt, bevor etwas gesendet wurde: %1 (%2):</translation>
    </message>
    <message>
        <source>
  and %1 more</source>
        <translation>
  und %1 weitere</translation>
    </message>
    <message>
        <source>reading it before the write</source>
        <translation>beim Lesen vor dem Schreiben</translation>
    </message>
    <message>
        <source> Reading it back failed too: %1</source>
        <translation> Auch das Zurücklesen schlug fehl: %1</translation>
    </message>
    <message>
        <source>read back after the error &quot;%1&quot;</source>
        <translation>nach dem Fehler „%1“ zurückgelesen</translation>
    </message>
    <message>
        <source>not sent: the connection failed at %1; nothing after it was sent</source>
        <translation>nicht gesendet: die Verbindung brach bei %1 ab; nichts danach wurde gesendet</translation>
    </message>
    <message>
        <source>the device held %1, not %2 as last read</source>
        <translation>das Gerät enthielt %1, nicht %2 wie zuletzt gelesen</translation>
    </message>
    <message>
        <source>reading the settings</source>
        <translation>Einstellungen werden gelesen</translation>
    </message>
    <message>
        <source>reading the users</source>
        <translation>Benutzer werden gelesen</translation>
    </message>
    <message>
        <source>read everything</source>
        <translation>alles gelesen</translation>
    </message>
    <message>
        <source>reading program %1</source>
        <translation>Programm %1 wird gelesen</translation>
    </message>
    <message>
        <source>reading dead times</source>
        <translation>Totzeiten werden gelesen</translation>
    </message>
    <message>
        <source>Output names</source>
        <translation>Ausgangsnamen</translation>
    </message>
    <message>
        <source>reading output names</source>
        <translation>Ausgangsnamen werden gelesen</translation>
    </message>
    <message>
        <source>Output names: %1</source>
        <translation>Ausgangsnamen: %1</translation>
    </message>
    <message>
        <source>reading users</source>
        <translation>Benutzer werden gelesen</translation>
    </message>
    <message>
        <source>PLC networks</source>
        <translation>SPS-Netzwerke</translation>
    </message>
    <message>
        <source>reading PLC networks</source>
        <translation>SPS-Netzwerke werden gelesen</translation>
    </message>
    <message>
        <source>reading the EEPROM</source>
        <translation>EEPROM wird gelesen</translation>
    </message>
    <message>
        <source>%1 The device was not changed.</source>
        <translation>%1 Das Gerät wurde nicht verändert.</translation>
    </message>
    <message>
        <source>step 1 of 2: safety backup</source>
        <translation>Schritt 1 von 2: Sicherheitskopie</translation>
    </message>
    <message>
        <source>Cannot take the safety backup before the restore: %1 The device was not changed.</source>
        <translation>Die Sicherheitskopie vor der Wiederherstellung ist nicht möglich: %1 Das Gerät wurde nicht verändert.</translation>
    </message>
    <message>
        <source>Cancelled before the restore started. The device was not changed.</source>
        <translation>Abgebrochen, bevor die Wiederherstellung begann. Das Gerät wurde nicht verändert.</translation>
    </message>
    <message>
        <source>step 2 of 2: restore</source>
        <translation>Schritt 2 von 2: Wiederherstellung</translation>
    </message>
    <message>
        <source> No safety backup was taken.</source>
        <translation> Es wurde keine Sicherheitskopie erstellt.</translation>
    </message>
    <message>
        <source> The device&apos;s previous content is in the safety backup %1.</source>
        <translation> Der vorherige Inhalt des Geräts ist in der Sicherheitskopie %1.</translation>
    </message>
    <message>
        <source>the device equals %1 (%2 blocks)</source>
        <translation>das Gerät gleicht %1 (%2 Blöcke)</translation>
    </message>
    <message>
        <source>the device differs from %1: device %2 blocks, image %3 blocks</source>
        <translation>das Gerät weicht von %1 ab: Gerät %2 Blöcke, Abbild %3 Blöcke</translation>
    </message>
    <message>
        <source>; first differing blocks: %1</source>
        <translation>; erste abweichende Blöcke: %1</translation>
    </message>
    <message>
        <source>%1 was written but does not read back as the image taken; check the disk</source>
        <translation>%1 wurde geschrieben, liest sich aber nicht als das erstellte Abbild zurück; prüfen Sie den Datenträger</translation>
    </message>
    <message>
        <source>scanning the line</source>
        <translation>Leitung wird abgesucht</translation>
    </message>
    <message>
        <source>no device answered on the line (numbers 0..63); check the cable, the baud rate and the protocol</source>
        <translation>kein Gerät hat auf der Leitung geantwortet (Nummern 0..63); prüfen Sie Kabel, Baudrate und Protokoll</translation>
    </message>
    <message>
        <source>cannot create the folder %1; choose another one</source>
        <translation>der Ordner %1 kann nicht angelegt werden; wählen Sie einen anderen</translation>
    </message>
    <message>
        <source>not backed up: the run was cancelled</source>
        <translation>nicht gesichert: der Lauf wurde abgebrochen</translation>
    </message>
    <message>
        <source>saved by an earlier run</source>
        <translation>von einem früheren Lauf gesichert</translation>
    </message>
    <message>
        <source>line backed up</source>
        <translation>Leitung gesichert</translation>
    </message>
    <message>
        <source>not verified: its backup failed (%1)</source>
        <translation>nicht geprüft: seine Sicherung schlug fehl (%1)</translation>
    </message>
    <message>
        <source>%1 is missing or was changed since the backup (SHA-256 differs from the manifest)</source>
        <translation>%1 fehlt oder wurde seit der Sicherung verändert (SHA-256 weicht vom Verzeichnis ab)</translation>
    </message>
    <message>
        <source>line verified</source>
        <translation>Leitung geprüft</translation>
    </message>
    <message>
        <source>Setting %1: %2.</source>
        <translation>Einstellung %1: %2.</translation>
    </message>
    <message>
        <source>to delete</source>
        <translation>zu löschen</translation>
    </message>
    <message>
        <source>1 problem</source>
        <translation>1 Problem</translation>
    </message>
    <message>
        <source>%1 problems</source>
        <translation>%1 Probleme</translation>
    </message>
    <message>
        <source> (before: %1)</source>
        <translation> (vorher: %1)</translation>
    </message>
    <message>
        <source>device %1</source>
        <translation>Gerät %1</translation>
    </message>
    <message>
        <source>device %1: </source>
        <translation>Gerät %1: </translation>
    </message>
    <message>
        <source>Users</source>
        <translation>Benutzer</translation>
    </message>
    <message>
        <source>restore</source>
        <translation>Wiederherstellen</translation>
    </message>
    <message>
        <source>1 item: %1</source>
        <translation>1 Element: %1</translation>
    </message>
    <message>
        <source>acknowledged; reading it back failed: %1</source>
        <translation>quittiert; Zurücklesen fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>the device acknowledged the write, but reads back another value</source>
        <translation>das Gerät hat das Schreiben quittiert, liest aber einen anderen Wert zurück</translation>
    </message>
    <message>
        <source>error reset (0x02)</source>
        <translation>Fehlerquittierung (0x02)</translation>
    </message>
    <message>
        <source>device status now: %1</source>
        <translation>Gerätestatus jetzt: %1</translation>
    </message>
    <message>
        <source>reading the device status failed: %1</source>
        <translation>Lesen des Gerätestatus fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>; the cause is still there: check the encoder and the outputs</source>
        <translation>; die Ursache besteht noch: prüfen Sie Geber und Ausgänge</translation>
    </message>
    <message>
        <source>active program (0x03)</source>
        <translation>aktives Programm (0x03)</translation>
    </message>
    <message>
        <source>program %1</source>
        <translation>Programm %1</translation>
    </message>
    <message>
        <source>program %1, output %2 (0x05)</source>
        <translation>Programm %1, Ausgang %2 (0x05)</translation>
    </message>
    <message>
        <source>dead time of output %1 (0x07)</source>
        <translation>Totzeit von Ausgang %1 (0x07)</translation>
    </message>
    <message>
        <source>normal, %1</source>
        <translation>normal, %1</translation>
    </message>
    <message>
        <source>on/off, switch-on %1, switch-off %2</source>
        <translation>Ein/Aus, Einschalten %1, Ausschalten %2</translation>
    </message>
    <message>
        <source>path-time, switch-on %1, switching time %2</source>
        <translation>Weg-Zeit, Einschalten %1, Schaltzeit %2</translation>
    </message>
    <message>
        <source>dead-time mode of output %1</source>
        <translation>Totzeit-Modus von Ausgang %1</translation>
    </message>
    <message>
        <source>Output %1: the dead time %2 and the dead time of its dead-time mode %3 differ, but the device holds one value for both.</source>
        <translation>Ausgang %1: die Totzeit %2 und die Totzeit seines Totzeit-Modus %3 unterscheiden sich, das Gerät hält aber einen Wert für beide.</translation>
    </message>
    <message>
        <source>reading dead-time modes</source>
        <translation>Lesen der Totzeit-Modi</translation>
    </message>
    <message>
        <source>no base points</source>
        <translation>keine Stützpunkte</translation>
    </message>
    <message numerus="yes">
        <source>%n base point(s): %1</source>
        <translation>
            <numerusform>%n Stützpunkt: %1</numerusform>
            <numerusform>%n Stützpunkte: %1</numerusform>
        </translation>
    </message>
    <message>
        <source>program %1, changed slowly</source>
        <translation>Programm %1, langsam umgeschaltet</translation>
    </message>
    <message>
        <source>program %1, changed directly (within one cycle)</source>
        <translation>Programm %1, direkt umgeschaltet (innerhalb eines Zyklus)</translation>
    </message>
    <message>
        <source>program %1, changed at the actual value %2</source>
        <translation>Programm %1, am Istwert %2 umgeschaltet</translation>
    </message>
    <message>
        <source>program %1, select mode %2</source>
        <translation>Programm %1, Umschaltart %2</translation>
    </message>
    <message>
        <source>locked (changes stay in RAM only)</source>
        <translation>gesperrt (Änderungen nur im RAM)</translation>
    </message>
    <message>
        <source>unlocked</source>
        <translation>entsperrt</translation>
    </message>
    <message>
        <source>analogue output %1</source>
        <translation>Analogausgang %1</translation>
    </message>
    <message>
        <source>programming program</source>
        <translation>Programmierprogramm</translation>
    </message>
    <message>
        <source>EEPROM lock</source>
        <translation>EEPROM-Sperre</translation>
    </message>
    <message>
        <source>Analogue output %1 is to be written twice.</source>
        <translation>Analogausgang %1 soll zweimal geschrieben werden.</translation>
    </message>
    <message>
        <source>Writing the cams changed the programming program; setting it back to %1 failed (%2): check it on the Programming program page.</source>
        <translation>Das Schreiben der Nocken hat das Programmierprogramm geändert; das Zurücksetzen auf %1 ist fehlgeschlagen (%2): prüfen Sie es auf der Seite Programmierprogramm.</translation>
    </message>
    <message>
        <source>Whether the device&apos;s EEPROM is locked could not be read (%1): if it is, what was written is held in RAM only and is lost when the device is switched off.</source>
        <translation>Ob das EEPROM des Geräts gesperrt ist, konnte nicht gelesen werden (%1): wenn ja, steht das Geschriebene nur im RAM und geht beim Ausschalten des Geräts verloren.</translation>
    </message>
    <message>
        <source>The device&apos;s EEPROM is locked: what was written is held in RAM only and is lost when the device is switched off. Unlock the EEPROM to keep it.</source>
        <translation>Das EEPROM des Geräts ist gesperrt: das Geschriebene steht nur im RAM und geht beim Ausschalten des Geräts verloren. Entsperren Sie das EEPROM, um es zu behalten.</translation>
    </message>
    <message>
        <source>reading the programming program</source>
        <translation>lese das Programmierprogramm</translation>
    </message>
    <message>
        <source>Reading the programs selected program %1 as the programming program; setting it back to program %2 failed: %3</source>
        <translation>Das Lesen der Programme hat Programm %1 als Programmierprogramm gewählt; das Zurücksetzen auf Programm %2 ist fehlgeschlagen: %3</translation>
    </message>
    <message>
        <source>reading analogue output %1</source>
        <translation>lese Analogausgang %1</translation>
    </message>
    <message>
        <source>reading the EEPROM lock</source>
        <translation>lese die EEPROM-Sperre</translation>
    </message>
    <message>
        <source>memory %1–%2</source>
        <translation>Speicher %1–%2</translation>
    </message>
    <message>
        <source>Reading variables</source>
        <translation>Variablen lesen</translation>
    </message>
    <message>
        <source>Reading flags</source>
        <translation>Merker lesen</translation>
    </message>
    <message>
        <source>Reading memory</source>
        <translation>Speicher lesen</translation>
    </message>
    <message>
        <source>the file was taken from an %1, the controller is an %2 (variables of other widths, flags elsewhere): nothing was written</source>
        <translation>die Datei stammt von einer %1, die Steuerung ist eine %2 (Variablen anderer Breite, Merker an anderer Stelle): nichts wurde geschrieben</translation>
    </message>
    <message>
        <source>the file&apos;s flags are on page %1, the %2 keeps them on page %3: nothing was written</source>
        <translation>die Merker der Datei liegen auf Seite %1, die %2 hält sie auf Seite %3: nichts wurde geschrieben</translation>
    </message>
    <message>
        <source>the file holds memory ranges, which the %1 cannot write (an MC200 V2 can): nothing was written</source>
        <translation>die Datei enthält Speicherbereiche, die die %1 nicht schreiben kann (eine MC200 V2 kann es): nichts wurde geschrieben</translation>
    </message>
    <message>
        <source>written, as read back after: %1</source>
        <translation>geschrieben, wie das Zurücklesen danach zeigt: %1</translation>
    </message>
    <message>
        <source>the %1 has no memory telegrams (an MC200 has): leave out --mem</source>
        <translation>die %1 hat keine Speichertelegramme (eine MC200 hat sie): lassen Sie --mem weg</translation>
    </message>
    <message>
        <source>Writing variables</source>
        <translation>Variablen schreiben</translation>
    </message>
    <message>
        <source>read back %1</source>
        <translation>zurückgelesen %1</translation>
    </message>
    <message>
        <source>the other %1 flags</source>
        <translation>die übrigen %1 Merker</translation>
    </message>
    <message>
        <source>Writing flags</source>
        <translation>Merker schreiben</translation>
    </message>
    <message>
        <source>the bytes read back differ from those written</source>
        <translation>die zurückgelesenen Bytes weichen von den geschriebenen ab</translation>
    </message>
    <message>
        <source>Writing memory</source>
        <translation>Speicher schreiben</translation>
    </message>
    <message>
        <source>%1 read %2 times, no two answers in a row agreed: the line damages answers (check the cable, its shield and the baud rate)</source>
        <translation>%1 %2-mal gelesen, keine zwei Antworten hintereinander stimmten überein: die Leitung beschädigt Antworten (prüfen Sie das Kabel, seine Schirmung und die Baudrate)</translation>
    </message>
    <message>
        <source>Reading objects</source>
        <translation>Objekte werden gelesen</translation>
    </message>
    <message>
        <source>%1: file %2, drive: %3</source>
        <translation>%1: Datei %2, Antrieb: %3</translation>
    </message>
    <message>
        <source>%1: file %2, drive %3</source>
        <translation>%1: Datei %2, Antrieb %3</translation>
    </message>
    <message>
        <source>Comparing objects</source>
        <translation>Objekte werden verglichen</translation>
    </message>
    <message>
        <source>the file&apos;s value of %1 cannot be written: %2. Nothing was written</source>
        <translation>der Wert von %1 in der Datei kann nicht geschrieben werden: %2. Nichts wurde geschrieben</translation>
    </message>
    <message>
        <source>%1 is not in the file: nothing was written</source>
        <translation>%1 ist nicht in der Datei: nichts wurde geschrieben</translation>
    </message>
    <message>
        <source>Writing objects</source>
        <translation>Objekte werden geschrieben</translation>
    </message>
    <message>
        <source>the drive took it but reads back %1</source>
        <translation>der Antrieb nahm es an, liest aber %1 zurück</translation>
    </message>
    <message>
        <source>Written</source>
        <translation>Geschrieben</translation>
    </message>
    <message>
        <source>not stored, because not every object was written</source>
        <translation>nicht gespeichert, weil nicht jedes Objekt geschrieben wurde</translation>
    </message>
    <message>
        <source>%1 was not sent: the check only reads</source>
        <translation>%1 wurde nicht gesendet: die Prüfung liest nur</translation>
    </message>
    <message>
        <source>%1 %2 was not loaded: %3</source>
        <translation>%1 %2 wurde nicht geladen: %3</translation>
    </message>
    <message>
        <source>no family&apos;s check takes %1</source>
        <translation>die Prüfung keiner Gerätefamilie nimmt %1</translation>
    </message>
    <message>
        <source>There is no check for %1 devices yet.</source>
        <translation>Für %1-Geräte gibt es noch keine Prüfung.</translation>
    </message>
    <message>
        <source>%1 is a table of %2 devices; the device connected is a %3 device: leave the option out</source>
        <translation>%1 ist eine Tabelle für %2-Geräte; das verbundene Gerät ist ein %3-Gerät: lassen Sie die Option weg</translation>
    </message>
    <message>
        <source>this device has no analogue outputs</source>
        <translation>dieses Gerät hat keine Analogausgänge</translation>
    </message>
    <message>
        <source>this device has analogue outputs 1..%1 only</source>
        <translation>dieses Gerät hat nur die Analogausgänge 1..%1</translation>
    </message>
    <message>
        <source>%1; its base points are not written</source>
        <translation>%1; seine Stützpunkte werden nicht geschrieben</translation>
    </message>
    <message>
        <source>Settings the device does not know, not read: %1.</source>
        <translation>Einstellungen, die das Gerät nicht kennt, nicht gelesen: %1.</translation>
    </message>
    <message>
        <source>Analogue cams: this device has no analogue outputs, so it has no analogue cams.</source>
        <translation>Analognocken: Dieses Gerät hat keine Analogausgänge, also auch keine Analognocken.</translation>
    </message>
    <message>
        <source>There is no check for the protocol %1 yet.</source>
        <translation>Für das Protokoll %1 gibt es noch keine Prüfung.</translation>
    </message>
    <message>
        <source>it asks with a text</source>
        <translation>es fragt mit einem Text</translation>
    </message>
    <message>
        <source>the device does not know it (:Z): %1</source>
        <translation>das Gerät kennt es nicht (:Z): %1</translation>
    </message>
    <message>
        <source>it answered ERR %1 when asked with 0</source>
        <translation>es antwortete ERR %1 auf die Frage mit 0</translation>
    </message>
    <message>
        <source>the device stopped answering</source>
        <translation>das Gerät antwortet nicht mehr</translation>
    </message>
    <message>
        <source>%1 is answered as manual %2 reads%3</source>
        <translation>%1 wird so beantwortet, wie wir Handbuch %2 lesen%3</translation>
    </message>
    <message>
        <source> (provisional format)</source>
        <translation> (vorläufiges Format)</translation>
    </message>
    <message>
        <source>a request under a new block number is answered, and so is a repeat of that number (with the last reply, not executed again)</source>
        <translation>eine Anfrage mit neuer Blocknummer wird beantwortet, ebenso eine Wiederholung dieser Nummer (mit der letzten Antwort, nicht noch einmal ausgeführt)</translation>
    </message>
    <message>
        <source>no answer under block numbers %1 (of %2, %2, %3)</source>
        <translation>keine Antwort unter den Blocknummern %1 (von %2, %2, %3)</translation>
    </message>
    <message>
        <source>every user in the bus&apos;s table gets the token within a second (P11: each answers within T = 10 ms)</source>
        <translation>jeder Teilnehmer in der Tabelle des Busses erhält das Token innerhalb einer Sekunde (P11: jeder antwortet innerhalb T = 10 ms)</translation>
    </message>
    <message>
        <source>not a Cam-BUS line</source>
        <translation>keine Cam-BUS-Leitung</translation>
    </message>
    <message>
        <source>no token heard in %1 ms</source>
        <translation>in %1 ms kein Token gehört</translation>
    </message>
    <message>
        <source>%1 tokens in %2 ms</source>
        <translation>%1 Token in %2 ms</translation>
    </message>
    <message>
        <source>%1; users %2 did not get the token</source>
        <translation>%1; die Teilnehmer %2 erhielten das Token nicht</translation>
    </message>
    <message>
        <source>area %1 word %2 can be read: %3</source>
        <translation>Bereich %1 Wort %2 ist lesbar: %3</translation>
    </message>
    <message>
        <source> (provisional: %1)</source>
        <translation> (vorläufig: %1)</translation>
    </message>
    <message>
        <source>area 203 word 38 holds the number of analogue outputs (0..14), and only their areas 241.. exist</source>
        <translation>Bereich 203 Wort 38 enthält die Anzahl der Analogausgänge (0..14), und nur deren Bereiche ab 241 gibt es</translation>
    </message>
    <message>
        <source>it says %1</source>
        <translation>es meldet %1</translation>
    </message>
    <message>
        <source>this variant of the protocol cannot address the word</source>
        <translation>diese Variante des Protokolls kann das Wort nicht adressieren</translation>
    </message>
    <message>
        <source>the variant shows in RDVAR&apos;s width, then in SYSDATA or RDBLOCK being answered</source>
        <translation>die Variante zeigt sich an der Breite von RDVAR, dann daran, ob SYSDATA oder RDBLOCK beantwortet wird</translation>
    </message>
    <message>
        <source>RDVAR answers 24 bits on an MC100 and 32 bits on an MC200, two&apos;s complement (P3)</source>
        <translation>RDVAR antwortet auf einer MC100 mit 24 Bit, auf einer MC200 mit 32 Bit, im Zweierkomplement (P3)</translation>
    </message>
    <message>
        <source>flag Mn read by itself and bit n-1 of the flags&apos; external RAM page agree</source>
        <translation>Merker Mn einzeln gelesen und Bit n-1 der externen RAM-Seite der Merker stimmen überein</translation>
    </message>
    <message>
        <source>read by themselves, %1 differ from the page (or changed between the reads)</source>
        <translation>einzeln gelesen weichen %1 von der Seite ab (oder änderten sich zwischen den Lesevorgängen)</translation>
    </message>
    <message>
        <source>inputs E1..E8 and outputs A1..A8 are read at the addresses of tables 47/48 and answered</source>
        <translation>die Eingänge E1..E8 und Ausgänge A1..A8 werden an den Adressen der Tabellen 47/48 gelesen und beantwortet</translation>
    </message>
    <message>
        <source>RDTABLE answers for each logical axis 1..8 the controller has (logical n is physical n-1)</source>
        <translation>RDTABLE antwortet für jede logische Achse 1..8, die die Steuerung hat (logisch n ist physisch n-1)</translation>
    </message>
    <message>
        <source>this variant has no axis telegrams</source>
        <translation>diese Variante hat keine Achstelegramme</translation>
    </message>
    <message>
        <source>axes %1 (%2)</source>
        <translation>Achsen %1 (%2)</translation>
    </message>
    <message>
        <source>the axis parameter table in use (%1)</source>
        <translation>die verwendete Achsparametertabelle (%1)</translation>
    </message>
    <message>
        <source>the controller has no axes (%1)</source>
        <translation>die Steuerung hat keine Achsen (%1)</translation>
    </message>
    <message>
        <source>the %1 of axis %2 is RDSTAT parameter %3 (0x%4)</source>
        <translation>der Wert %1 der Achse %2 ist RDSTAT-Parameter %3 (0x%4)</translation>
    </message>
    <message>
        <source>the %1 of axis %2 (the table names no parameter for it)</source>
        <translation>der Wert %1 der Achse %2 (die Tabelle nennt keinen Parameter dafür)</translation>
    </message>
    <message>
        <source>not in the table, not read</source>
        <translation>nicht in der Tabelle, nicht gelesen</translation>
    </message>
    <message>
        <source>answered %1</source>
        <translation>antwortete %1</translation>
    </message>
    <message>
        <source>%1: file: not on the drive it was read from, drive %2 (left as it is)</source>
        <translation>%1: Datei: nicht auf dem Antrieb, von dem sie gelesen wurde, Antrieb %2 (bleibt, wie er ist)</translation>
    </message>
    <message>
        <source>not on this drive</source>
        <translation>nicht auf diesem Antrieb</translation>
    </message>
    <message>
        <source>the file is from a drive of type %1 (&quot;%2&quot;), the connected drive is of type %3 (&quot;%4&quot;): nothing was written. Restore it with --force (GUI: &quot;Write to another drive type&quot;) only if you know the objects mean the same on both</source>
        <translation>die Datei stammt von einem Antrieb des Typs %1 („%2“), der verbundene Antrieb ist vom Typ %3 („%4“): nichts wurde geschrieben. Stellen Sie sie mit --force (GUI: „In einen anderen Antriebstyp schreiben“) nur wieder her, wenn Sie wissen, dass die Objekte in beiden dasselbe bedeuten</translation>
    </message>
    <message>
        <source>store set %1 in the drive&apos;s flash (1904.%1 = $32)</source>
        <translation>Satz %1 im Flash des Antriebs speichern (1904.%1 = $32)</translation>
    </message>
    <message>
        <source>not on this drive (%1): not written</source>
        <translation>nicht auf diesem Antrieb (%1): nicht geschrieben</translation>
    </message>
    <message>
        <source>store the sets in the drive&apos;s flash (1904.n = $32)</source>
        <translation>die Sätze im Flash des Antriebs speichern (1904.n = $32)</translation>
    </message>
    <message>
        <source>the info string (_?) starts with &quot;Compax3&quot; and its second word is the drive type (C7)</source>
        <translation>der Info-String (_?) beginnt mit &quot;Compax3&quot;, und sein zweites Wort ist der Gerätetyp (C7)</translation>
    </message>
    <message>
        <source>O1.4 and O1,4 name the same object (the manual writes &apos;,&apos;, the public client &apos;.&apos;)</source>
        <translation>O1.4 und O1,4 bezeichnen dasselbe Objekt (das Handbuch schreibt &apos;,&apos;, der öffentliche Client &apos;.&apos;)</translation>
    </message>
    <message>
        <source>O1,4 answered %1, O1.4 answered %2</source>
        <translation>O1,4 antwortete %1, O1.4 antwortete %2</translation>
    </message>
    <message>
        <source>a whole number asked for in hex ($) is answered with its $ (C8)</source>
        <translation>eine hexadezimal ($) erfragte ganze Zahl wird mit ihrem $ beantwortet (C8)</translation>
    </message>
    <message>
        <source>an object the drive lacks is refused with !%1 (C5)</source>
        <translation>ein Objekt, das der Antrieb nicht hat, wird mit !%1 abgelehnt (C5)</translation>
    </message>
    <message>
        <source>a text asked for in hex is refused with !0006 (C5, C8)</source>
        <translation>ein hexadezimal erfragter Text wird mit !0006 abgelehnt (C5, C8)</translation>
    </message>
    <message>
        <source>object %1 (%2) exists and is %3</source>
        <translation>Objekt %1 (%2) existiert und ist %3</translation>
    </message>
    <message>
        <source>program %1 does not exist: the device reports no programs; read its identity again or check the connection</source>
        <translation>Programm %1 gibt es nicht: Das Gerät meldet keine Programme; lesen Sie seine Kennung erneut oder prüfen Sie die Verbindung</translation>
    </message>
    <message>
        <source>program %1 does not exist on the device (it has programs 0 to %2): choose one of those</source>
        <translation>Programm %1 gibt es auf dem Gerät nicht (es hat die Programme 0 bis %2): wählen Sie eines davon</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>nicht verbunden</translation>
    </message>
    <message>
        <source>the %1 family has no backup</source>
        <translation>die Familie %1 hat keine Sicherung</translation>
    </message>
    <message>
        <source>failed: %1</source>
        <translation>fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>not reached: %1</source>
        <translation>nicht erreicht: %1</translation>
    </message>
    <message>
        <source>incomplete: %1</source>
        <translation>unvollständig: %1</translation>
    </message>
    <message>
        <source>%1 is a device of the %2 family in one folder and of the %3 family in the other: not compared</source>
        <translation>%1 ist im einen Ordner ein Gerät der Familie %2 und im anderen der Familie %3: nicht verglichen</translation>
    </message>
    <message>
        <source>machine name %1 → %2</source>
        <translation>Maschinenname %1 → %2</translation>
    </message>
    <message>
        <source>%1: family %2 → %3</source>
        <translation>%1: Familie %2 → %3</translation>
    </message>
    <message>
        <source>%1: %2 → %3</source>
        <translation>%1: %2 → %3</translation>
    </message>
    <message>
        <source>%1: volatile items %2 → %3</source>
        <translation>%1: flüchtige Elemente %2 → %3</translation>
    </message>
    <message>
        <source>not saved in %1%2</source>
        <translation>nicht gesichert in %1%2</translation>
    </message>
    <message>
        <source>another device: %1 → %2</source>
        <translation>anderes Gerät: %1 → %2</translation>
    </message>
    <message>
        <source>%1 is no machine backup folder: %2 (made by `machine backup`)</source>
        <translation>%1 ist kein Maschinen-Sicherungsordner: %2 (erstellt von `machine backup`)</translation>
    </message>
    <message>
        <source>%1: added</source>
        <translation>%1: hinzugefügt</translation>
    </message>
    <message>
        <source>%1: added (%2)</source>
        <translation>%1: hinzugefügt (%2)</translation>
    </message>
    <message>
        <source>%1: taken out of the machine</source>
        <translation>%1: aus der Maschine genommen</translation>
    </message>
    <message>
        <source> and %1 more</source>
        <translation> und %1 weitere</translation>
    </message>
    <message>
        <source>machine</source>
        <translation>Maschine</translation>
    </message>
    <message>
        <source>first version</source>
        <translation>erste Version</translation>
    </message>
    <message>
        <source>first version: %1</source>
        <translation>erste Version: %1</translation>
    </message>
    <message>
        <source>No temporary folder to take version %1 out of %2 into: %3</source>
        <translation>Kein temporärer Ordner, um Version %1 aus %2 dorthin zu holen: %3</translation>
    </message>
    <message>
        <source>%1 not saved: no version was stored (a version without a device would read as the device taken out of the machine).</source>
        <translation>%1 nicht gesichert: es wurde keine Version gespeichert (eine Version ohne ein Gerät sähe aus, als sei das Gerät aus der Maschine genommen).</translation>
    </message>
    <message>
        <source>The backup could not be compared with the latest version, no version was stored: %1</source>
        <translation>Die Sicherung konnte nicht mit der letzten Version verglichen werden, es wurde keine Version gespeichert: %1</translation>
    </message>
    <message>
        <source>Communication settings left out: %1 (the device keeps %2). They decide how the device is reached and are written only when asked for by name.</source>
        <translation>Kommunikationseinstellungen ausgelassen: %1 (das Gerät behält %2). Sie bestimmen, wie das Gerät erreicht wird, und werden nur geschrieben, wenn sie ausdrücklich verlangt werden.</translation>
    </message>
    <message>
        <source>its own</source>
        <translation>seine eigenen</translation>
    </message>
    <message>
        <source>Whether the communication settings changed is not known: if the next connection fails, try the settings that were to be written.</source>
        <translation>Ob sich die Kommunikationseinstellungen geändert haben, ist nicht bekannt: schlägt die nächste Verbindung fehl, versuchen Sie die Einstellungen, die geschrieben werden sollten.</translation>
    </message>
    <message>
        <source>Communication settings written: the next connection to this device needs %1.</source>
        <translation>Kommunikationseinstellungen geschrieben: die nächste Verbindung zu diesem Gerät braucht %1.</translation>
    </message>
    <message>
        <source>The image holds the communication settings the device had when it was taken, %1 (it uses %2 now). A restore puts them back with everything else: the next connection to the device needs %1.</source>
        <translation>Das Abbild enthält die Kommunikationseinstellungen, die das Gerät bei der Aufnahme hatte, %1 (jetzt verwendet es %2). Eine Wiederherstellung stellt sie mit allem anderen zurück: die nächste Verbindung zum Gerät braucht %1.</translation>
    </message>
    <message>
        <source>EEPROM: blocks %1 differ%2</source>
        <translation>EEPROM: Blöcke %1 unterscheiden sich%2</translation>
    </message>
    <message>
        <source>blocks</source>
        <translation>Blöcke</translation>
    </message>
    <message>
        <source> (a backup of the older format: its content is not decoded)</source>
        <translation> (eine Sicherung im älteren Format: ihr Inhalt wird nicht entschlüsselt)</translation>
    </message>
    <message>
        <source> (the decoded content is equal: what differs is not in it)</source>
        <translation> (der entschlüsselte Inhalt ist gleich: der Unterschied liegt nicht darin)</translation>
    </message>
    <message>
        <source>the device reports %1</source>
        <translation>das Gerät meldet %1</translation>
    </message>
    <message>
        <source>The backup</source>
        <translation>Die Sicherung</translation>
    </message>
    <message>
        <source>the flag page</source>
        <translation>die Merkerseite</translation>
    </message>
    <message>
        <source>%1: %2 bytes differ, from %3: %4 → %5</source>
        <translation>%1: %2 Bytes unterscheiden sich, ab %3: %4 → %5</translation>
    </message>
    <message>
        <source>variant</source>
        <translation>Variante</translation>
    </message>
    <message>
        <source>The parameter set</source>
        <translation>Der Parametersatz</translation>
    </message>
    <message>
        <source>not on the drive it was read from</source>
        <translation>nicht auf dem Antrieb, von dem gelesen wurde</translation>
    </message>
    <message>
        <source>the file&apos;s</source>
        <translation>laut Datei</translation>
    </message>
    <message>
        <source>drive</source>
        <translation>Antrieb</translation>
    </message>
    <message>
        <source>not on the drive</source>
        <translation>nicht auf dem Antrieb</translation>
    </message>
    <message>
        <source>machine file: %1</source>
        <translation>Maschinendatei: %1</translation>
    </message>
    <message>
        <source>%1 EEPROM blocks (%2 bytes), decoded: %3 programs</source>
        <translation>%1 EEPROM-Blöcke (%2 Bytes), entschlüsselt: %3 Programme</translation>
    </message>
    <message>
        <source>a safety copy of what the device holds now is saved first%1</source>
        <translation>zuerst wird eine Sicherheitskopie des jetzigen Inhalts des Geräts angelegt%1</translation>
    </message>
    <message>
        <source>then the whole EEPROM is erased and written again: %1 blocks, and the device starts</source>
        <translation>dann wird das ganze EEPROM gelöscht und neu geschrieben: %1 Blöcke, und das Gerät startet</translation>
    </message>
    <message>
        <source> (a safety copy was saved to %1)</source>
        <translation> (eine Sicherheitskopie wurde in %1 gesichert)</translation>
    </message>
    <message>
        <source>EEPROM, %1 blocks</source>
        <translation>EEPROM, %1 Blöcke</translation>
    </message>
    <message>
        <source>erased or partly written</source>
        <translation>gelöscht oder teilweise geschrieben</translation>
    </message>
    <message>
        <source>%1 variables and %2 flags of the %3</source>
        <translation>%1 Variablen und %2 Merker der %3</translation>
    </message>
    <message>
        <source>only the differing variables, flags and memory are written, each read back</source>
        <translation>nur die abweichenden Variablen, Merker und Speicher werden geschrieben, jedes zurückgelesen</translation>
    </message>
    <message>
        <source>%1 objects of %2 (serial number %3)</source>
        <translation>%1 Objekte von %2 (Seriennummer %3)</translation>
    </message>
    <message>
        <source>; %1 objects are not on this drive</source>
        <translation>; %1 Objekte sind nicht auf diesem Antrieb</translation>
    </message>
    <message>
        <source>%1: not saved: %2</source>
        <translation>%1: nicht gesichert: %2</translation>
    </message>
    <message>
        <source>%1 objects are not on this drive, nor on the file&apos;s</source>
        <translation>%1 Objekte sind nicht auf diesem Antrieb und nicht auf dem der Datei</translation>
    </message>
    <message>
        <source>%1: not compared: %2</source>
        <translation>%1: nicht verglichen: %2</translation>
    </message>
    <message>
        <source>only the differing objects are written, each read back; control words and functions never from a file</source>
        <translation>nur die abweichenden Objekte werden geschrieben, jedes zurückgelesen; Steuerwörter und Funktionen nie aus einer Datei</translation>
    </message>
    <message>
        <source>not saved in the version%1</source>
        <translation>in der Version nicht gesichert%1</translation>
    </message>
    <message>
        <source>its backup now %1</source>
        <translation>die Sicherung jetzt: %1</translation>
    </message>
    <message>
        <source>not read from the device now</source>
        <translation>jetzt nicht vom Gerät gelesen</translation>
    </message>
</context>
</TS>
