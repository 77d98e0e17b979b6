{ GLAux.pas -- the one GLAUX call the textbook uses (§13.1.1, F28):
  auxDIBImageLoad reads a Windows BMP (24-bit, uncompressed: BITMAPFILEHEADER
  + BITMAPINFOHEADER, rows bottom-up in BGR padded to 4 bytes) into an
  AUX_RGBImageRec of tightly packed RGB rows, bottom-up as glTexImage2D
  wants them.  nil if the file is missing or not such a BMP. }
unit GLAux;

{$mode delphi}

interface

type
  TAUX_RGBImageRec = record
    sizeX, sizeY: LongInt;
    data: PByte;
  end;
  PAUX_RGBImageRec = ^TAUX_RGBImageRec;

function auxDIBImageLoad(const FileName: string): PAUX_RGBImageRec;

implementation

uses SysUtils, Classes;

function auxDIBImageLoad(const FileName: string): PAUX_RGBImageRec;
var
  f: TFileStream;
  hdr: array[0..53] of Byte;
  offBits, w, h, bpp, comp, rowLen, x, y: LongInt;
  row: array of Byte;
  topDown: Boolean;
  dst: PByte;
begin
  Result := nil;
  if not FileExists(FileName) then Exit;
  f := TFileStream.Create(FileName, fmOpenRead or fmShareDenyWrite);
  try
    if f.Read(hdr, 54) <> 54 then Exit;
    if (hdr[0] <> Ord('B')) or (hdr[1] <> Ord('M')) then Exit;
    offBits := PLongInt(@hdr[10])^;
    w := PLongInt(@hdr[18])^;
    h := PLongInt(@hdr[22])^;
    bpp := PWord(@hdr[28])^;
    comp := PLongInt(@hdr[30])^;
    if (bpp <> 24) or (comp <> 0) or (w <= 0) or (h = 0) then Exit;
    topDown := h < 0;
    h := Abs(h);
    rowLen := (w * 3 + 3) and not 3;
    SetLength(row, rowLen);
    New(Result);
    Result^.sizeX := w;
    Result^.sizeY := h;
    GetMem(Result^.data, w * h * 3);
    f.Position := offBits;
    for y := 0 to h - 1 do
    begin
      f.ReadBuffer(row[0], rowLen);
      if topDown then dst := Result^.data + (h - 1 - y) * w * 3
      else dst := Result^.data + y * w * 3;
      for x := 0 to w - 1 do
      begin
        dst[x * 3] := row[x * 3 + 2];
        dst[x * 3 + 1] := row[x * 3 + 1];
        dst[x * 3 + 2] := row[x * 3];
      end;
    end;
  finally
    f.Free;
  end;
end;

end.
